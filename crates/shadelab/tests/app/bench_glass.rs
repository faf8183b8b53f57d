//! `bench glass`'s measurements on lavapipe (docs/transparency.md), at a small size and one frame
//! a row: each step towards the exact path brings the glass closer to the f64 Whitted reference
//! (opaque, straight through, the back-face exit, the analytic exit), and the absorption rule
//! errs only where it replaces the exact form, by less than the chapter's bounds allow.

use shadelab::bench::glass::{markdown, methods, rule};
use shadelab_render::{AdapterChoice, Gpu};

#[test]
fn each_step_towards_the_exact_path_comes_closer_to_the_reference() {
    let gpu = Gpu::headless(AdapterChoice::from_env()).expect("a GPU adapter (lavapipe)");
    let rows = methods(&gpu, (240, 135), 1, 1).expect("measured");
    let error = |name: &str| rows.iter().find(|r| r.method.starts_with(name)).unwrap().mean_error;
    let (opaque, straight, back, analytic) =
        (error("opaque"), error("glass, straight"), error("glass, back-face"), error("glass, analytic"));
    eprintln!("opaque {opaque:.4}, straight {straight:.4}, back faces {back:.4}, analytic {analytic:.4}");
    assert!(opaque > straight && straight > back && back > analytic, "{rows:?}");
    assert!(rows.iter().all(|r| r.median_ms.is_finite() && r.median_ms > 0.0));
    let (rules, maps) = rule(&gpu, (240, 135), 1, 1, &[0.19, 0.49, 1.0]).expect("measured");
    assert_eq!(maps.len(), 2, "a map just under each threshold");
    // Neglected below 0.2: under 1 − e^(−0.2) of the light through; linear below 0.5: under
    // 0.107 of it; exact above: no difference at all.
    assert!(rules[0].max_error > 0.0 && rules[0].max_error < 0.181, "{:?}", rules[0]);
    assert!(rules[1].max_error > 0.0 && rules[1].max_error < 0.107, "{:?}", rules[1]);
    assert_eq!(rules[2].max_error, 0.0, "{:?}", rules[2]);
    assert!(rules[1].max_error < rules[0].max_error, "the linear form is closer than neglecting");
    let md = markdown(&rows, &rules, "lavapipe", "test");
    assert!(md.contains("| 0.19 | neglected |") && md.contains("| 0.49 | linear 1 − a·d |"), "{md}");
}
