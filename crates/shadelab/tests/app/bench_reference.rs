//! `bench reference` and the reference on a mesh past the old brute-force limit of 10⁴ triangles
//! (docs/reference.md): correctness only; the times are reported, never asserted.

use crate::common::{out_dir, render, shadelab};

/// A 20 000-triangle generated sphere renders as a reference (through its hierarchy), and `bench
/// reference` reports its triangles, its hierarchy's bytes and both timings.
#[test]
fn a_large_mesh_has_a_reference_and_bench_reference_reports_it() {
    let dir = out_dir().join("bench-reference");
    let _ = std::fs::remove_dir_all(&dir);
    let d = dir.to_str().unwrap();
    let o = shadelab(&["bench", "mesh", "--triangles", "20000", "--out", d, "--width", "32", "--height", "18"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let glb = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .find(|p| p.extension().is_some_and(|x| x == "glb"))
        .expect("bench mesh wrote a .glb");
    let (scene, png) = (glb.to_str().unwrap(), dir.join("reference.png"));
    let img = render(&["--reference", "--scene", scene], (64, 36), &png).to_rgba8();
    // The sphere is in the middle of the view, lit; the corner is the background.
    assert!(img.get_pixel(32, 18)[0] > 2 * img.get_pixel(0, 0)[0].max(20), "{:?}", img.get_pixel(32, 18));
    let o = shadelab(&["bench", "reference", "--scene", scene, "--width", "32", "--height", "18", "--runs", "1"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let out = String::from_utf8_lossy(&o.stdout);
    let row = out.lines().find(|l| l.starts_with(&format!("| {scene} |"))).unwrap_or_else(|| panic!("{out}"));
    let cells: Vec<&str> = row.trim_matches('|').split('|').map(str::trim).collect();
    let triangles: usize = cells[1].parse().unwrap();
    let bytes_each: f64 = cells[4].parse().unwrap();
    assert!(triangles >= 20_000, "{row}");
    // Nodes and the triangle order, about 36 bytes a triangle: more means a leaf per triangle.
    assert!(bytes_each > 10.0 && bytes_each < 80.0, "{row}");
    let o = shadelab(&["bench", "reference", "--runs", "0"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--runs"));
}
