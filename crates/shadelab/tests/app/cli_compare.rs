//! `shadelab compare` from the outside: the error numbers of one PNG against another, the map,
//! the --max-flip exit, and bad pairs as one line and exit 2.

use crate::common::{error_lines, out_dir, shadelab};

#[test]
fn compare_gives_the_error_numbers_and_refuses_bad_pairs() {
    let dir = out_dir();
    let (a, b, c) = (dir.join("cmp-a.png"), dir.join("cmp-b.png"), dir.join("cmp-c.png"));
    for (path, shading, width) in [(&a, "phong", "64"), (&b, "flat", "64"), (&c, "phong", "32")] {
        let o = shadelab(&[
            "render",
            "--shading",
            shading,
            "--width",
            width,
            "--height",
            "36",
            "--output",
            path.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    }
    let text = |o: &std::process::Output| String::from_utf8_lossy(&o.stdout).into_owned();
    let same = shadelab(&["compare", a.to_str().unwrap(), a.to_str().unwrap()]);
    assert!(same.status.success());
    assert!(text(&same).starts_with("FLIP mean 0.0000, RMSE 0.000e0, max 0.000, 0.00 %"), "{}", text(&same));
    let map = dir.join("cmp-map.png");
    let differ = shadelab(&["compare", a.to_str().unwrap(), b.to_str().unwrap(), "--map", map.to_str().unwrap()]);
    assert!(differ.status.success());
    let flip: f64 = text(&differ).split_whitespace().nth(2).unwrap().trim_end_matches(',').parse().unwrap();
    assert!(flip > 0.005, "flat against Phong shading differs: {}", text(&differ));
    assert_eq!(image::image_dimensions(&map).unwrap(), (64, 36));
    let over = shadelab(&["compare", a.to_str().unwrap(), b.to_str().unwrap(), "--max-flip", "0.001"]);
    assert_eq!(over.status.code(), Some(1), "above --max-flip fails the run");
    for (args, needle) in [
        (vec!["compare", a.to_str().unwrap(), c.to_str().unwrap()], "same size"),
        (vec!["compare", a.to_str().unwrap(), "nowhere.png"], "nowhere.png"),
        (vec!["compare", a.to_str().unwrap(), a.to_str().unwrap(), "--max-flip", "2"], "[0, 1]"),
    ] {
        let o = shadelab(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        let lines = error_lines(&o);
        assert!(lines.len() == 1 && lines[0].contains(needle), "{args:?}: {lines:?}");
    }
}
