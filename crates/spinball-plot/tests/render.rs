//! Rendering into real PNG files: sizes, bad data, and the pictures' pixels.

use std::path::{Path, PathBuf};

use spinball_geometry::{DVec2, Sinai, Stadium, Table};
use spinball_plot::{
    Colorbar, Grid, HistogramPlot, LineKind, LinePlot, Marker, Plot, PlotError, Series, TablePlot,
    viridis,
};

/// A fresh directory for this test's files.
fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("spinball-plot-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Width and height from a PNG's IHDR chunk, after checking the signature.
fn png_size(path: &Path) -> (u32, u32) {
    let bytes = std::fs::read(path).unwrap();
    assert!(
        bytes.len() > 1000,
        "{} is only {} bytes",
        path.display(),
        bytes.len()
    );
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n", "PNG signature");
    assert_eq!(&bytes[12..16], b"IHDR");
    let be = |i: usize| u32::from_be_bytes([bytes[i], bytes[i + 1], bytes[i + 2], bytes[i + 3]]);
    (be(16), be(20))
}

fn lambda_plot() -> LinePlot {
    let alpha = [0.0, 0.1, 0.5, 1.0];
    LinePlot::new()
        .title("λ(α)")
        .x_label("α = I/(m r²)")
        .y_label("λ (1/time)")
        .series(
            Series::new(
                "stadium",
                alpha.iter().copied().zip([0.43, 0.28, 0.183, 0.147]),
            )
            .errors([0.004, 0.003, 0.002, 0.002])
            .band([0.42, 0.27, 0.17, 0.14], [0.44, 0.29, 0.19, 0.15])
            .band_label("spread"),
        )
        .series(
            Series::new(
                "Sinai",
                alpha.iter().copied().zip([0.43, 0.211, 0.119, 0.102]),
            )
            .kind(LineKind::Dashed),
        )
        .hline(0.0, "λ = 0")
}

#[test]
fn every_plot_writes_a_png_of_the_asked_size() {
    let dir = temp_dir("sizes");
    let stadium = Stadium::new(1.0).unwrap();
    let path: Vec<DVec2> = (0..50)
        .map(|i| DVec2::new((i as f64 * 0.7).sin() * 1.5, (i as f64 * 1.3).cos() * 0.9))
        .collect();

    let f = dir.join("table.png");
    TablePlot::new(&stadium)
        .title("stadium")
        .trajectory(path.clone())
        .save_png(&f, 800, 500)
        .unwrap();
    assert_eq!(png_size(&f), (800, 500));

    let f = dir.join("lines.png");
    lambda_plot().save_png(&f, 1200, 800).unwrap();
    assert_eq!(png_size(&f), (1200, 800));

    let f = dir.join("log.png");
    LinePlot::new()
        .log_y(true)
        .series(Series::new("ΔE", (1..100).map(|n| (n as f64, 1e-16 * n as f64))).markers_only())
        .save_png(&f, 640, 480)
        .unwrap();
    assert_eq!(png_size(&f), (640, 480));

    let f = dir.join("hist.png");
    HistogramPlot::new((0..1000).map(|i| (i as f64 * 0.37).sin()))
        .bins(30)
        .density(true)
        .marker(Marker::new("mean", 0.0))
        .marker(Marker::new("median", 0.1).kind(LineKind::Dotted))
        .save_png(&f, 1000, 700)
        .unwrap();
    assert_eq!(png_size(&f), (1000, 700));

    let f = dir.join("grid.png");
    let tables: Vec<Table> = [
        "circle",
        "rectangle:L=1.5,H=1",
        "stadium:a=1",
        "sinai:L=2,R=1",
    ]
    .iter()
    .map(|s| s.parse().unwrap())
    .collect();
    let mut grid = Grid::new(2, 2).title("tables");
    for t in &tables {
        grid.push(TablePlot::new(t).title(t.name()));
    }
    grid.colorbar(Colorbar::new("collision number", 0.0, 500.0))
        .save_png(&f, 1000, 900)
        .unwrap();
    assert_eq!(png_size(&f), (1000, 900));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn nan_points_are_skipped_not_fatal() {
    let dir = temp_dir("nan");
    let f = dir.join("nan.png");
    LinePlot::new()
        .series(
            Series::new(
                "with holes",
                [
                    (0.0, 1.0),
                    (1.0, f64::NAN),
                    (2.0, 3.0),
                    (f64::INFINITY, 1.0),
                    (3.0, 2.0),
                ],
            )
            .errors([0.1, 0.1, f64::NAN, 0.1, 0.2]),
        )
        .save_png(&f, 600, 400)
        .unwrap();
    assert_eq!(png_size(&f), (600, 400));

    // Non-positive values on a log axis are skipped too.
    let f = dir.join("log.png");
    LinePlot::new()
        .log_y(true)
        .series(Series::new(
            "ΔE",
            [(1.0, 0.0), (2.0, 1e-16), (3.0, -1.0), (4.0, 2e-16)],
        ))
        .save_png(&f, 600, 400)
        .unwrap();
    assert!(f.exists());

    let f = dir.join("traj.png");
    let sinai = Sinai::new(2.0, 1.0).unwrap();
    let path = [
        DVec2::new(-1.5, -1.5),
        DVec2::new(f64::NAN, 0.0),
        DVec2::new(2.0, 0.5),
        DVec2::new(0.0, 2.0),
    ];
    TablePlot::new(&sinai)
        .trajectory(path)
        .save_png(&f, 500, 500)
        .unwrap();
    assert_eq!(png_size(&f), (500, 500));

    let f = dir.join("hist.png");
    HistogramPlot::new([1.0, f64::NAN, 2.0, 2.5, f64::NEG_INFINITY])
        .marker(Marker::new("undefined", f64::NAN))
        .save_png(&f, 500, 400)
        .unwrap();
    assert!(f.exists());
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn empty_data_is_an_error_and_writes_nothing() {
    let dir = temp_dir("empty");
    let cases: Vec<(&str, Result<(), PlotError>)> = vec![
        (
            "no_series",
            LinePlot::new().save_png(dir.join("a.png"), 400, 300),
        ),
        (
            "all_nan",
            LinePlot::new()
                .series(Series::new("nan", [(f64::NAN, 1.0), (1.0, f64::NAN)]))
                .save_png(dir.join("b.png"), 400, 300),
        ),
        (
            "log_nonpositive",
            LinePlot::new()
                .log_y(true)
                .series(Series::new("zeros", [(1.0, 0.0), (2.0, 0.0)]))
                .save_png(dir.join("c.png"), 400, 300),
        ),
        (
            "hist_empty",
            HistogramPlot::new(Vec::<f64>::new()).save_png(dir.join("d.png"), 400, 300),
        ),
        (
            "trajectory_nan",
            TablePlot::new(&Stadium::new(1.0).unwrap())
                .trajectory([DVec2::NAN, DVec2::NAN])
                .save_png(dir.join("e.png"), 400, 300),
        ),
        (
            "grid_empty",
            Grid::new(2, 2).save_png(dir.join("f.png"), 400, 300),
        ),
    ];
    for (name, r) in cases {
        assert!(matches!(r, Err(PlotError::EmptyData(_))), "{name}: {r:?}");
    }
    let left: Vec<_> = std::fs::read_dir(&dir).unwrap().collect();
    assert!(left.is_empty(), "files left behind: {left:?}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn other_bad_input_is_a_typed_error() {
    let dir = temp_dir("bad");
    let r = LinePlot::new()
        .series(Series::new("s", [(0.0, 1.0), (1.0, 2.0)]).errors([0.1]))
        .save_png(dir.join("a.png"), 400, 300);
    assert!(
        matches!(
            r,
            Err(PlotError::LengthMismatch {
                expected: 2,
                got: 1,
                ..
            })
        ),
        "{r:?}"
    );
    let r = lambda_plot().save_png(dir.join("a.jpg"), 400, 300);
    assert!(
        matches!(r, Err(PlotError::Invalid { what: "path", .. })),
        "{r:?}"
    );
    let r = lambda_plot().save_png(dir.join("a.png"), 10, 300);
    assert!(matches!(r, Err(PlotError::TooSmall { .. })), "{r:?}");
    let r = lambda_plot()
        .log_y(true)
        .y_range(-1.0, 1.0)
        .save_png(dir.join("a.png"), 400, 300);
    assert!(matches!(r, Err(PlotError::Invalid { .. })), "{r:?}");
    let r = Grid::new(1, 1)
        .panel(lambda_plot())
        .panel(lambda_plot())
        .save_png(dir.join("a.png"), 400, 300);
    assert!(
        matches!(r, Err(PlotError::GridFull { panels: 2, .. })),
        "{r:?}"
    );
    assert!(!dir.join("a.png").exists());
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn trajectory_is_coloured_by_the_colormap_ends() {
    // A two-leg trajectory: the first leg is viridis(0), the last viridis(1).
    // Decode nothing: look for the exact colours in the raw RGB by drawing
    // into a memory buffer.
    use spinball_plot::plotters::prelude::*;
    let stadium = Stadium::new(1.0).unwrap();
    let plot = TablePlot::new(&stadium).trajectory([
        DVec2::new(-1.5, 0.2),
        DVec2::new(0.0, 0.9),
        DVec2::new(1.5, -0.5),
    ]);
    let (w, h) = (600u32, 320u32);
    let mut buf = vec![0u8; (w * h * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut buf, (w, h)).into_drawing_area();
        root.fill(&WHITE).unwrap();
        plot.draw(&root, &spinball_plot::Style::for_size(w, h))
            .unwrap();
        root.present().unwrap();
    }
    let has = |c: spinball_plot::RGBColor| buf.chunks(3).any(|p| p == [c.0, c.1, c.2]);
    assert!(has(viridis(0.0)), "dark start colour drawn");
    assert!(has(viridis(1.0)), "light end colour drawn");
}

#[test]
fn phase_space_plots_draw_and_refuse_bad_data() {
    use spinball_plot::{MapPlot, Scatter3d};
    let dir = temp_dir("phase");
    let cells: Vec<Option<f64>> = (0..12)
        .map(|k| (k != 5).then_some(k as f64 / 12.0))
        .collect();
    let mask: Vec<bool> = (0..12).map(|k| k % 4 == 1).collect();
    let map = MapPlot::new((0.0, 4.0), (-1.0, 1.0), (0.0, 1.0))
        .cells(4, 3, cells.clone())
        .outline(mask)
        .points(vec![(1.0, 0.5, 0.3), (f64::NAN, 0.0, 0.1)])
        .markers(vec![
            (2.0, 0.0, spinball_plot::palette(1)),
            (f64::NAN, 0.0, spinball_plot::palette(2)),
        ])
        .labels("s", "sin θ")
        .title("map");
    let path = dir.join("map.png");
    map.save_png(&path, 600, 400).unwrap();
    assert_eq!(png_size(&path), (600, 400));
    let cloud = Scatter3d::new(
        vec![([0.5, 0.0, 0.1], 0.2), ([1.0, 0.5, -0.2], 0.9)],
        [(0.0, 1.0), (-1.0, 1.0), (-1.0, 1.0)],
        (0.0, 1.0),
    )
    .labels("s", "sin θ", "u");
    let path = dir.join("cloud.png");
    cloud.save_png(&path, 500, 500).unwrap();
    assert_eq!(png_size(&path), (500, 500));
    // Wrong lengths, ranges and empty data are errors, and nothing is written.
    let short = MapPlot::new((0.0, 4.0), (-1.0, 1.0), (0.0, 1.0)).cells(4, 4, cells.clone());
    assert!(matches!(
        short.validate(),
        Err(PlotError::LengthMismatch { .. })
    ));
    let mask = MapPlot::new((0.0, 4.0), (-1.0, 1.0), (0.0, 1.0))
        .cells(4, 3, cells)
        .outline(vec![true; 3]);
    assert!(matches!(
        mask.validate(),
        Err(PlotError::LengthMismatch { .. })
    ));
    let flat = MapPlot::new((0.0, 4.0), (1.0, 1.0), (0.0, 1.0)).points(vec![(1.0, 1.0, 0.5)]);
    assert!(matches!(flat.validate(), Err(PlotError::Invalid { .. })));
    let empty = MapPlot::new((0.0, 4.0), (-1.0, 1.0), (0.0, 1.0)).cells(1, 1, vec![None]);
    assert!(matches!(empty.validate(), Err(PlotError::EmptyData(_))));
    assert!(empty.save_png(dir.join("empty.png"), 300, 300).is_err());
    assert!(!dir.join("empty.png").exists());
    let nothing = Scatter3d::new(vec![], [(0.0, 1.0); 3], (0.0, 1.0));
    assert!(nothing.validate().is_err());
}
