//! CSV tables of analysis results that are neither one
//! [`SweepRow`] per point nor one row per trajectory (those two are the
//! result schema's, `spinball_analysis::report`): a compact per-estimate
//! summary, Lyapunov spectra, `ΔQ` pairs, and named histograms bin by bin.
//!
//! Figures publish the numbers behind their pictures; the columns of these
//! tables are fixed here, once, so every figure that writes, say, the
//! per-trajectory FTLEs writes them the same way.
//!
//! ```
//! use spinball_analysis::estimators::Histogram;
//! use spinball_figures::histograms_csv;
//!
//! let mut h = Histogram::new(0.0, 2.0, 2)?;
//! h.push(0.5);
//! let csv = histograms_csv("x", &[("demo", &h)]);
//! assert_eq!(csv.as_str(), "population,x_lo,x_hi,count\ndemo,-inf,0,0\ndemo,0,1,1\ndemo,1,2,0\n");
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use spinball_analysis::diagnostics::{DeltaQPopulation, PairClass, QPair, QPairStatistics};
use spinball_analysis::estimators::Histogram;
use spinball_analysis::report::SweepRow;
use spinball_analysis::run::SpectrumEstimate;

use crate::csv::{Csv, optional};
use crate::result_plots::SpectrumPair;

/// One line per record with the distribution's summary: α, ICs,
/// collisions, mean, SEM, median, std, conditional mean (empty if none),
/// chaotic fraction and its SEM, its band over the thresholds
/// (`band_min`, `band_max`) and the wall time (`wall_s`).
pub fn summary_csv(rows: &[SweepRow]) -> Csv {
    let mut csv = Csv::new(&[
        "alpha",
        "ics",
        "collisions",
        "mean",
        "sem",
        "median",
        "std",
        "conditional_mean",
        "chaotic_fraction",
        "chaotic_fraction_sem",
        "band_min",
        "band_max",
        "wall_s",
    ]);
    for r in rows {
        csv.row(&[
            &r.alpha,
            &r.n_ics,
            &r.collisions_per_ic,
            &r.mean,
            &r.sem,
            &r.median,
            &r.std,
            &optional(r.conditional_mean),
            &r.chaotic_fraction,
            &r.chaotic_fraction_sem,
            &r.chaotic_fraction_band_min,
            &r.chaotic_fraction_band_max,
            &r.wall_time_s,
        ]);
    }
    csv
}

/// One line per spectrum ensemble of a table (spec) at an α: table,
/// α, method, ICs, collisions, the five mean exponents `l1..l5`, their SEMs
/// `sem1..sem5`, the mean sum, the floored separations and the wall time.
pub fn spectra_csv(rows: &[(&str, f64, &SpectrumEstimate)]) -> Csv {
    let mut csv = Csv::with_columns(
        "table,alpha,method,ics,collisions,l1,l2,l3,l4,l5,\
         sem1,sem2,sem3,sem4,sem5,sum_mean,floored,wall_s",
    );
    for (table, alpha, e) in rows {
        let head = [
            table.to_string(),
            alpha.to_string(),
            e.options.method.name().to_string(),
            e.n_ics.to_string(),
            e.options.collisions.to_string(),
        ];
        let numbers = e.mean.iter().chain(&e.sem).chain([&e.sum_mean]);
        let tail = [e.floored.to_string(), e.wall_time_s.to_string()];
        csv.row_from(
            head.into_iter()
                .chain(numbers.map(f64::to_string))
                .chain(tail),
        );
    }
    csv
}

/// [`spectra_csv`] of the exact and finite-difference spectra of tables
/// (`(spec, spectra against α)`): per table and α, the exact row, then the
/// finite-difference one.
pub fn spectrum_pairs_csv(tables: &[(&str, &[SpectrumPair])]) -> Csv {
    let mut rows = Vec::new();
    for (spec, points) in tables {
        for (alpha, pair) in points.iter() {
            rows.extend(pair.iter().map(|e| (*spec, *alpha, e)));
        }
    }
    spectra_csv(&rows)
}

/// Every recorded pair of consecutive collisions: the collision, the
/// class, `ΔQ` and `v∥` before the flight (in exponent form).
pub fn q_pairs_csv(pairs: &[QPair]) -> Csv {
    let mut csv = Csv::with_columns("collision,class,dq,v_par_before_flight");
    for p in pairs {
        let (dq, v_par) = (format!("{:e}", p.dq), format!("{:e}", p.v_par));
        csv.row(&[&p.collision, &p.class.name(), &dq, &v_par]);
    }
    csv
}

/// The five `|ΔQ|` populations of `q` by name: the three pair classes
/// (`same_wall`, `facing_walls`, `turned`), `through_collision` and
/// `facing_residual`.
pub fn q_populations(q: &QPairStatistics) -> [(&'static str, &DeltaQPopulation); 5] {
    [
        (
            PairClass::SameWall.name(),
            q.population(PairClass::SameWall),
        ),
        (
            PairClass::FacingWalls.name(),
            q.population(PairClass::FacingWalls),
        ),
        (PairClass::Turned.name(), q.population(PairClass::Turned)),
        ("through_collision", &q.through_collision),
        ("facing_residual", &q.facing_residual),
    ]
}

/// The bins of named histograms of the quantity `axis` (e.g. `log10`):
/// columns `population`, `{axis}_lo`, `{axis}_hi`, `count`; per histogram a
/// row for the underflow (`-inf` to its lower edge), then one per bin.
pub fn histograms_csv(axis: &str, named: &[(&str, &Histogram)]) -> Csv {
    let (lo, hi) = (format!("{axis}_lo"), format!("{axis}_hi"));
    let mut csv = Csv::new(&["population", &lo, &hi, "count"]);
    for (name, h) in named {
        csv.row(&[name, &"-inf", &h.lo(), &h.underflow()]);
        let edges = h.edges();
        for (i, c) in h.counts().iter().enumerate() {
            csv.row(&[name, &edges[i], &edges[i + 1], c]);
        }
    }
    csv
}

#[cfg(test)]
mod tests {
    use super::*;
    use spinball_analysis::report::sweep_rows;
    use spinball_analysis::run::{Ensemble, Threads};
    use spinball_core::SpinLaw;
    use spinball_geometry::Stadium;

    #[test]
    fn summary_table() {
        let e = Ensemble::new(Stadium::new(1.0).unwrap(), SpinLaw::new(0.5).unwrap())
            .with_ics(5)
            .with_collisions(300)
            .with_threads(Threads::Fixed(1))
            .run()
            .unwrap();
        let s = summary_csv(&sweep_rows(std::slice::from_ref(&e)).unwrap());
        let lines: Vec<&str> = s.as_str().lines().collect();
        assert!(lines[0].contains(",band_min,band_max,wall_s"));
        let fields: Vec<&str> = lines[1].split(',').collect();
        assert_eq!(fields.len(), 13);
        assert_eq!(fields[3].parse::<f64>().unwrap(), e.mean());
    }

    #[test]
    fn spectrum_table() {
        use spinball_analysis::estimators::{Method, SpectrumOptions};
        use spinball_analysis::run::spectrum_ensemble;
        use spinball_core::{Billiard, Sampler};
        let billiard = Billiard::new(Stadium::new(1.0).unwrap(), SpinLaw::new(0.5).unwrap());
        let options = SpectrumOptions::new(200, Method::Tangent);
        let e = spectrum_ensemble(
            &billiard,
            Sampler::Paper,
            1,
            0..3,
            &options,
            Threads::Fixed(1),
        )
        .unwrap();
        let csv = spectra_csv(&[("stadium:a=1", 0.5, &e)]);
        let lines: Vec<&str> = csv.as_str().lines().collect();
        assert_eq!(lines[0].split(',').count(), 18);
        let fields: Vec<&str> = lines[1].split(',').collect();
        assert_eq!(fields.len(), 18);
        assert_eq!(fields[..5], ["stadium:a=1", "0.5", "tangent", "3", "200"]);
        assert_eq!(fields[5].parse::<f64>().unwrap(), e.mean[0]);
        assert_eq!(fields[14].parse::<f64>().unwrap(), e.sem[4]);
        let fd = spectrum_ensemble(
            &billiard,
            Sampler::Paper,
            1,
            0..3,
            &SpectrumOptions::new(200, Method::default()),
            Threads::Fixed(1),
        )
        .unwrap();
        let pairs = [(0.5, [e.clone(), fd.clone()]), (0.7, [e, fd])];
        let csv = spectrum_pairs_csv(&[("stadium:a=1", &pairs), ("sinai", &pairs[..1])]);
        let methods: Vec<String> = csv
            .as_str()
            .lines()
            .skip(1)
            .map(|l| l.split(',').take(3).collect::<Vec<_>>().join(","))
            .collect();
        assert_eq!(
            methods,
            [
                "stadium:a=1,0.5,tangent",
                "stadium:a=1,0.5,fd",
                "stadium:a=1,0.7,tangent",
                "stadium:a=1,0.7,fd",
                "sinai,0.5,tangent",
                "sinai,0.5,fd",
            ]
        );
    }

    #[test]
    fn q_tables() {
        use spinball_analysis::diagnostics::q_pair_statistics;
        use spinball_core::{Billiard, Sampler};
        let billiard = Billiard::new(Stadium::new(1.0).unwrap(), SpinLaw::new(0.5).unwrap());
        let start = Sampler::Paper.initial_state(billiard.table(), billiard.law(), 1, 0);
        let q = q_pair_statistics(&billiard, start, 200, true).unwrap();
        let csv = q_pairs_csv(&q.pairs);
        assert_eq!(csv.rows(), q.pairs.len());
        let first: Vec<&str> = csv.as_str().lines().nth(1).unwrap().split(',').collect();
        assert_eq!(first[1], q.pairs[0].class.name());
        assert_eq!(first[2].parse::<f64>().unwrap(), q.pairs[0].dq);
        let named = q_populations(&q);
        assert_eq!(
            named.map(|(n, _)| n)[..3],
            ["same_wall", "facing_walls", "turned"]
        );
        let classes: u64 = named[..3].iter().map(|(_, p)| p.count).sum();
        assert_eq!(classes, q.pair_count());
    }

    #[test]
    fn histogram_bins() {
        let mut h = Histogram::new(-2.0, 0.0, 2).unwrap();
        for x in [-5.0, -1.5, -0.5, -0.2] {
            h.push(x);
        }
        let csv = histograms_csv("log10", &[("a", &h), ("b", &h)]);
        assert_eq!(csv.rows(), 6);
        assert!(
            csv.as_str()
                .starts_with("population,log10_lo,log10_hi,count\n")
        );
        assert!(
            csv.as_str()
                .contains("a,-inf,-2,1\na,-2,-1,1\na,-1,0,2\nb,")
        );
    }
}
