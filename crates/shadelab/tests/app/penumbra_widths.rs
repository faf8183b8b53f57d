//! `bench penumbra`'s measurement on lavapipe (docs/area-lights.md): the 10–90 % width of the
//! plate's penumbra on the ground as it rises, against the similar-triangles prediction
//! w = size·h/(H − h). The f64 reference (the light's integral over 64² cells with binary
//! visibility against the plate) rises as 0.8·w, the 10–90 % of a square light's linear ramp;
//! PCSS and the light as 16 point sources (the mean of their hard shadows) follow it within 25 %;
//! PCF stays one texel wide whatever h. Prints the table docs/area-lights.md gives and writes
//! the bench's CSV, table and plot.

use shadelab::bench::penumbra::{HEIGHTS, OUTPUTS, SIDE, measure, write_outputs};
use shadelab_render::{AdapterChoice, Gpu};

#[test]
fn penumbra_widths_follow_the_similar_triangles() {
    let gpu = Gpu::headless(AdapterChoice::from_env()).expect("a GPU adapter (lavapipe)");
    let rows = measure(&gpu, &HEIGHTS, SIDE).expect("the widths are measured");
    let step = 1.0 / SIDE as f64;
    let mut table = Vec::new();
    for r in &rows {
        let h = r.plate_h;
        let exact = r.reference.expect("the reference crosses 10 % and 90 %");
        let pcss = r.pcss.expect("PCSS's profile crosses 10 % and 90 %");
        let points = r.points.expect("16 point sources' profile crosses 10 % and 90 %");
        let pcf = r.pcf.expect("PCF's profile crosses 10 % and 90 %");
        eprintln!(
            "PENUMBRA | {h} | {:.4} | {:.4} | {exact:.4} | {pcss:.4} | {points:.4} | {pcf:.4} |",
            r.predicted,
            0.8 * r.predicted
        );
        assert!((exact - 0.8 * r.predicted).abs() <= 0.05 * r.predicted + 2.0 * step, "h {h}: reference {exact}");
        assert!((pcss - exact).abs() <= 0.25 * exact + 2.0 * step, "h {h}: PCSS {pcss} against {exact}");
        // 16 hard shadows make a ramp of 16 steps: its crossings are off by up to two steps.
        assert!((points - exact).abs() <= 0.25 * exact + 2.0 * step, "h {h}: 16 points {points} against {exact}");
        table.push((exact, pcss, pcf));
    }
    // PCF's edge does not widen with the height; the reference's grows sixteenfold.
    let widest = table.last().unwrap().0;
    assert!(table.iter().all(|r| r.2 < 0.2 * widest), "PCF widths {table:?}");
    assert!(table.windows(2).all(|p| p[1].1 > p[0].1), "PCSS widths must grow with h: {table:?}");
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("bench-penumbra");
    write_outputs(&rows, &gpu.describe(), "test", &dir).expect("the outputs are written");
    for f in OUTPUTS {
        assert!(dir.join(f).is_file(), "{f} not written");
    }
}
