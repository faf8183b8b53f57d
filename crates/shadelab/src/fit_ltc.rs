//! `shadelab fit-ltc`: fit the LTC tables of every D afresh (`shadelab_model::ltc_fit`), print
//! each D's distance to its lobes, and with `--write` write the table the renderer reads.

use crate::Failure;
use crate::cli::FitLtcArgs;
use shadelab_model::lighting::ltc::{LTC_TABLE_SIDE, ltc_node_m, ltc_node_n_dot_v};
use shadelab_model::lighting::microfacet::Distribution;
use shadelab_model::ltc_fit::{entry_error, fit_tables, table_source};
use shadelab_model::params::NamedValue;

pub fn run(args: &FitLtcArgs) -> Result<(), Failure> {
    let start = web_time::Instant::now();
    let tables = fit_tables();
    println!(
        "fitted {} tables of {n}×{n} nodes in {:.1} s",
        tables.len(),
        start.elapsed().as_secs_f64(),
        n = LTC_TABLE_SIDE
    );
    for (&(name, d), table) in Distribution::ALL.iter().zip(&tables) {
        let errors: Vec<(f64, usize)> = table
            .iter()
            .enumerate()
            .map(|(k, &e)| (entry_error(d, ltc_node_n_dot_v(k % LTC_TABLE_SIDE), ltc_node_m(k / LTC_TABLE_SIDE), e), k))
            .collect();
        let mean = errors.iter().map(|e| e.0).sum::<f64>() / errors.len() as f64;
        let (worst, k) = errors.iter().copied().fold((0.0, 0), |a, b| if b.0 > a.0 { b } else { a });
        println!(
            "{name}: L1 distance to the lobe, mean {mean:.4}, largest {worst:.4} (m = {:.4}, N·V = {:.4})",
            ltc_node_m(k / LTC_TABLE_SIDE),
            ltc_node_n_dot_v(k % LTC_TABLE_SIDE)
        );
        if args.rows {
            for (j, row) in errors.chunks(LTC_TABLE_SIDE).enumerate() {
                let cells: Vec<String> = row.iter().map(|e| format!("{:.3}", e.0)).collect();
                println!("  m = {:.4}: {}", ltc_node_m(j), cells.join(" "));
            }
        }
    }
    if let Some(path) = &args.write {
        std::fs::write(path, table_source(&tables))
            .map_err(|e| Failure::Usage(format!("fit-ltc --write: {}: {e}", path.display())))?;
        println!("wrote {}", path.display());
    }
    Ok(())
}
