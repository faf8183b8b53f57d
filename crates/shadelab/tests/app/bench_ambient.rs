//! `bench ambient` (docs/reference.md): every rung of the ladder is reported, with its time and
//! its error against the truth; the times are reported, never asserted.

use crate::common::{error_lines, shadelab};

/// The table has the constant, fitted and occluded ambient and path tracing at 1 and 4 paths,
/// each error finite; more paths come closer to the truth, and the fitted I_a no further than
/// the constant one.
#[test]
fn bench_ambient_reports_every_rung() {
    let o = shadelab(&["bench", "ambient", "--width", "40", "--height", "24", "--truth-spp", "64", "--bounces", "3"]);
    assert_eq!(o.status.code(), Some(0), "{:?}", error_lines(&o));
    let out = String::from_utf8_lossy(&o.stdout);
    let rmse = |row: &str| -> f64 {
        let line = out.lines().find(|l| l.starts_with(row)).unwrap_or_else(|| panic!("no {row} in {out}"));
        line.rsplit('|').nth(1).unwrap().trim().parse().unwrap()
    };
    let rows =
        ["| constant I_a", "| fitted I_a", "| ambient occlusion", "| path traced, 1 paths", "| path traced, 16 paths"];
    for row in rows {
        assert!(rmse(row).is_finite() && rmse(row) > 0.0, "{row}: {out}");
    }
    assert!(rmse("| fitted I_a") <= rmse("| constant I_a"), "{out}");
    assert!(rmse("| path traced, 16 paths") < rmse("| path traced, 1 paths"), "{out}");
    assert!(out.contains("is not measured"), "{out}");
}
