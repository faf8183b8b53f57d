//! `shadelab bench shadows --quick` on lavapipe at a tiny size: a CSV row per resolution ×
//! filter plus shadows off and the baseline, every number finite, a larger PCF map no worse than
//! the smallest, and PCSS equal to PCF where no light has an area.

use std::process::Command;

#[test]
fn quick_run_writes_every_row_with_finite_numbers() {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("bench-shadows");
    let _ = std::fs::remove_dir_all(&dir);
    let o = Command::new(env!("CARGO_BIN_EXE_shadelab"))
        .args(["bench", "shadows", "--quick", "--width", "160", "--height", "90", "--frames", "2", "--output"])
        .arg(&dir)
        .env("SHADELAB_ADAPTER", "lavapipe")
        .output()
        .expect("run shadelab");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    for f in shadelab::bench::shadows::OUTPUTS {
        assert!(dir.join(f).is_file(), "{f} not written");
    }
    let text = std::fs::read_to_string(dir.join("shadows.csv")).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |name: &str| header.iter().position(|h| *h == name).unwrap_or_else(|| panic!("no column {name}"));
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    let resolutions = shadelab::bench::shadows::QUICK_RESOLUTIONS;
    let filters: Vec<&str> =
        shadelab::bench::shadows::FILTERS.iter().map(|f| shadelab::bench::shadows::filter_name(*f)).collect();
    assert_eq!(rows.len(), resolutions.len() * filters.len() + 2, "{text}");
    let find = |kind: &str, res: &str, filter: &str| {
        rows.iter()
            .find(|r| r[col("config")] == kind && r[col("resolution")] == res && r[col("filter")] == filter)
            .unwrap_or_else(|| panic!("no row {kind} {res} {filter}:\n{text}"))
    };
    let number = |r: &[&str], name: &str| -> f64 {
        let v: f64 = r[col(name)].parse().unwrap_or_else(|_| panic!("{name} = '{}'", r[col(name)]));
        assert!(v.is_finite(), "{name} = {v}");
        v
    };
    for res in resolutions {
        for &filter in &filters {
            let r = find("shadows", &res.to_string(), filter);
            for name in
                ["median_ms", "p10_ms", "p90_ms", "ratio_to_baseline", "ratio_to_off", "rmse", "share_disagreeing"]
            {
                number(r, name);
            }
        }
    }
    // The default scene has no area light: PCSS is PCF's compare there, the same image.
    for res in resolutions {
        let rmse = |filter: &str| number(find("shadows", &res.to_string(), filter), "rmse");
        assert_eq!(rmse("pcss"), rmse("pcf"), "at {res}");
    }
    let off = find("off", "", "");
    for name in ["median_ms", "ratio_to_baseline", "rmse", "share_disagreeing"] {
        number(off, name);
    }
    let base = find("baseline", "", "");
    assert_eq!(number(base, "ratio_to_baseline"), 1.0);
    assert!(base[col("rmse")].is_empty(), "the baseline has no error");
    let share = |res: u32| number(find("shadows", &res.to_string(), "pcf"), "share_disagreeing");
    let (small, large) = (share(resolutions[0]), share(*resolutions.last().unwrap()));
    assert!(
        large <= small,
        "PCF disagrees more at {}: {large} than at {}: {small}",
        resolutions.last().unwrap(),
        resolutions[0]
    );
}

/// With an area light the study adds PCSS at other tap counts, the light as k point sources and
/// its specular by LTC: each row is there with finite numbers, 16 point sources come nearer the
/// exact image than one, the LTC nearer than the representative point, and some rows are on the
/// Pareto front.
#[test]
fn an_area_light_scene_measures_every_method() {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("bench-shadows-area");
    let _ = std::fs::remove_dir_all(&dir);
    let o = Command::new(env!("CARGO_BIN_EXE_shadelab"))
        .args(["bench", "shadows", "--scene", "penumbra", "--quick", "--width", "160", "--height", "90"])
        .args(["--frames", "1", "--warmup", "0", "--output"])
        .arg(&dir)
        .env("SHADELAB_ADAPTER", "lavapipe")
        .output()
        .expect("run shadelab");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = std::fs::read_to_string(dir.join("shadows.csv")).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |name: &str| header.iter().position(|h| *h == name).unwrap_or_else(|| panic!("no column {name}"));
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    let rmse = |kind: &str, res: u32, field: &str, value: &str| -> f64 {
        let r = rows
            .iter()
            .find(|r| r[col("config")] == kind && r[col("resolution")] == res.to_string() && r[col(field)] == value)
            .unwrap_or_else(|| panic!("no row {kind} {res} {field}={value}:\n{text}"));
        let v: f64 = r[col("rmse")].parse().unwrap();
        assert!(v.is_finite() && r[col("median_ms")].parse::<f64>().unwrap().is_finite());
        v
    };
    for res in shadelab::bench::shadows::QUICK_RESOLUTIONS {
        for taps in shadelab::bench::shadows::PCSS_TAP_COUNTS {
            rmse("pcss-taps", res, "pcss_taps", &taps.to_string());
        }
        let by_k: Vec<f64> = shadelab::bench::shadows::POINT_COUNTS
            .iter()
            .map(|k| rmse("points", res, "points", &k.to_string()))
            .collect();
        assert!(by_k.last() < by_k.first(), "at {res}: RMSE by k {by_k:?}");
        // The LTC's specular over the light is nearer the exact integral than the representative
        // point's, with the same shadows.
        let (ltc, point) = (rmse("ltc", res, "filter", "pcss"), rmse("shadows", res, "filter", "pcss"));
        assert!(ltc < point, "at {res}: LTC {ltc} against the representative point {point}");
    }
    assert!(rows.iter().any(|r| r[col("pareto")] == "true"), "{text}");
}
