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
