//! Tables built from segments for the tests here and in the kernels, and
//! the tests of the lane casts of tables built from segments.

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64;
use spinball_geometry::{Boundary, DVec2, LineSegment};

use super::super::agree::{check, check_n, d};
use super::*;
use crate::isa::Baseline;

fn line(a: DVec2, b: DVec2) -> Segment {
    Segment::Line(LineSegment::new(a, b).unwrap())
}

fn arc(c: DVec2, r: f64, start: f64, sweep: f64) -> Segment {
    Segment::Arc(ArcSegment::new(c, r, start, sweep).unwrap())
}

/// The stadium of half-length `a`: bottom, right cap, top, left cap.
pub(crate) fn stadium(a: f64) -> SegmentTable {
    SegmentTable::new(vec![
        line(d(-a, -1.0), d(a, -1.0)),
        arc(d(a, 0.0), 1.0, -FRAC_PI_2, PI),
        line(d(a, 1.0), d(-a, 1.0)),
        arc(d(-a, 0.0), 1.0, FRAC_PI_2, PI),
    ])
    .unwrap()
}

/// The Sinai table: the box `[-l, l]²` and a clockwise hole of radius `r`.
fn sinai(l: f64, r: f64) -> SegmentTable {
    SegmentTable::with_holes(
        vec![
            line(d(-l, -l), d(l, -l)),
            line(d(l, -l), d(l, l)),
            line(d(l, l), d(-l, l)),
            line(d(-l, l), d(-l, -l)),
        ],
        vec![vec![arc(DVec2::ZERO, r, 0.0, -TAU)]],
    )
    .unwrap()
}

/// The mushroom of the `SegmentTable` docs: cap radius `r`, stem
/// half-width `w`, stem height `h`.
pub(crate) fn mushroom(r: f64, w: f64, h: f64) -> SegmentTable {
    SegmentTable::new(vec![
        line(d(-w, -h), d(w, -h)),
        line(d(w, -h), d(w, 0.0)),
        line(d(w, 0.0), d(r, 0.0)),
        arc(DVec2::ZERO, r, 0.0, PI),
        line(d(-r, 0.0), d(-w, 0.0)),
        line(d(-w, 0.0), d(-w, -h)),
    ])
    .unwrap()
}

/// A star-shaped 20-gon with alternating radii (1 and 0.81..0.99), no
/// fixed seed needed: the operation counts' 20-segment table.
pub(crate) fn alternating_twenty_gon() -> SegmentTable {
    let v: Vec<DVec2> = (0..20)
        .map(|k| {
            let radius = if k % 2 == 0 {
                1.0
            } else {
                0.8 + 0.01 * k as f64
            };
            DVec2::from_angle(TAU * k as f64 / 20.0) * radius
        })
        .collect();
    SegmentTable::polygon(&v).unwrap()
}

fn l_shape() -> SegmentTable {
    SegmentTable::polygon(&[
        d(0.0, 0.0),
        d(2.0, 0.0),
        d(2.0, 1.0),
        d(1.0, 1.0),
        d(1.0, 2.0),
        d(0.0, 2.0),
    ])
    .unwrap()
}

/// A star-shaped, non-convex 20-gon with random radii (fixed seed).
fn twenty_gon() -> SegmentTable {
    let mut rng = Pcg64::seed_from_u64(20);
    let v: Vec<DVec2> = (0..20)
        .map(|k| DVec2::from_angle(TAU * k as f64 / 20.0) * rng.random_range(0.6..1.2))
        .collect();
    SegmentTable::polygon(&v).unwrap()
}

/// The table's corners and junctions: rays into every wall end from
/// the reference point and from a few sampled points, and rays grazing
/// along every flat wall from just inside it.
fn junction_rays(t: &SegmentTable) -> Vec<(DVec2, DVec2)> {
    let mut rng = Pcg64::seed_from_u64(5);
    let mut from: Vec<DVec2> = (0..4).map(|_| t.sample_interior(&mut rng, 1.0)).collect();
    from.push(t.reference_point());
    let mut rays = Vec::new();
    for w in t.walls() {
        for o in &from {
            rays.push((*o, w.start() - *o));
            rays.push((*o, w.end() - *o));
        }
        if let Segment::Line(l) = w {
            let along = l.end() - l.start();
            let mid = l.start() + 0.5 * along;
            for eps in [0.0, 1e-15, 1e-12, 1e-9] {
                let o = mid + l.normal() * eps * t.length_scale();
                rays.push((o, along));
                rays.push((o, -along));
                rays.push((o, along + l.normal() * 1e-13));
                rays.push((o, -along - l.normal() * 1e-13));
            }
            // From one end along the wall and from the start across the
            // table.
            rays.push((l.start(), along));
            rays.push((l.start(), l.normal()));
            rays.push((l.end(), l.normal() - along));
        }
    }
    rays.push((from[0], DVec2::ZERO));
    rays
}

/// Both views (curved and, without arcs, flat) against the scalar cast.
fn check_table(t: &SegmentTable, special: &[(DVec2, DVec2)]) {
    let lanes = LaneSegments::new(t);
    let mut rays = junction_rays(t);
    rays.extend_from_slice(special);
    check(t, &lanes.view::<true>(), &rays);
    if !lanes.is_curved() {
        check_n(t, &lanes.view::<false>(), &rays, 2_000);
    }
}

/// A triangle on a horizontal base whose right side is two collinear
/// walls: a wall along an axis among oblique ones, and an oblique wall
/// that shares its neighbour's normal.
fn split_triangle() -> SegmentTable {
    SegmentTable::polygon(&[d(-1.0, 0.0), d(1.0, 0.0), d(0.5, 0.5), d(0.0, 1.0)]).unwrap()
}

#[test]
fn pairs_and_axis_walls_are_found_and_ids_kept() {
    let ids = |t: &SegmentTable| -> Vec<String> {
        let l = LaneSegments::new(t);
        let flats = l.steps.iter().map(|st| match st {
            Step::One(f, false) => format!("{}", f.id),
            // Reuses the previous wall's `−(v·n)` and `v·dir`.
            Step::One(f, true) => format!("{}~", f.id),
            Step::Pair(a, b) => format!("{}+{}", a.id, b.id),
            // Walls along an axis: `a`, and `|` if vertical.
            Step::AxisOne(a, shares) => format!(
                "a{}{}{}",
                a.id,
                if a.upright { "|" } else { "" },
                if *shares { "~" } else { "" }
            ),
            // Two walls on one line: `a=b`.
            Step::AxisLine(a, b, shares) => format!(
                "a{}{}{}={}",
                a.id,
                if a.upright { "|" } else { "" },
                if *shares { "~" } else { "" },
                b.id
            ),
            Step::AxisPair(a, b) => {
                format!("a{}+{}{}", a.id, b.id, if a.upright { "|" } else { "" })
            }
        });
        let arcs = l.arcs.iter().map(|c| format!("arc{}", c.id));
        flats.chain(arcs).collect()
    };
    // Stadium: the flat walls 0 and 2 are a horizontal pair, cast at 2.
    assert_eq!(ids(&stadium(1.0)), ["a0+2", "arc1", "arc3"]);
    // Sinai: (0, 2) and (1, 3), then the hole.
    assert_eq!(ids(&sinai(2.0, 1.0)), ["a0+2", "a1+3|", "arc4"]);
    // Mushroom: only the stem's sides (1, 5) face opposite ways; the
    // stem's floor (0) and the cap's floor (2, 4) face the same way,
    // and the cap's floor's two halves lie on one line.
    assert_eq!(
        ids(&mushroom(1.0, 0.3, 1.0)),
        ["a0", "a2~=4", "a1+5|", "arc3"]
    );
    // A square standing on a corner: two oblique pairs.
    let diamond =
        SegmentTable::polygon(&[d(1.0, 0.0), d(0.0, 1.0), d(-1.0, 0.0), d(0.0, -1.0)]).unwrap();
    assert_eq!(ids(&diamond), ["0+2", "1+3"]);
    // The base along the x axis; walls 1 and 2 share a normal.
    assert_eq!(ids(&split_triangle()), ["a0", "1", "2~", "3"]);
}

/// `Geom::land_both` against two `Geom::land`s, every field of every
/// lane bitwise, on `L` lanes: pairs of rays `1e-9` apart (a reference
/// and its shadow, nearly always one wall) and unrelated pairs (walls
/// differing in some lane). Returns how many pairs shared every wall
/// and how many did not. `cpu` proves this CPU runs `L`.
fn land_both_is_two_landings<L: Lanes>(cpu: L::Needs, t: &SegmentTable) -> (usize, usize) {
    let lanes = LaneSegments::new(t);
    let g = lanes.view::<true>();
    let mut rng = Pcg64::seed_from_u64(8);
    let mut shared = (0, 0);
    let load = |v: &[f64]| L::load(cpu, v);
    for pair in 0..4_000 {
        let mut a = [[0.0; 4]; crate::lanes::MAX_LANES];
        let mut b = [[0.0; 4]; crate::lanes::MAX_LANES];
        for j in 0..L::N {
            let o = t.sample_interior(&mut rng, 1.0);
            let v = DVec2::from_angle(rng.random::<f64>() * TAU);
            a[j] = [o.x, o.y, v.x, v.y];
            b[j] = if pair % 2 == 0 {
                [o.x + 1e-9, o.y - 1e-9, v.x, v.y + 1e-9]
            } else {
                let o = t.sample_interior(&mut rng, 1.0);
                let v = DVec2::from_angle(rng.random::<f64>() * TAU);
                [o.x, o.y, v.x, v.y]
            };
        }
        let column =
            |z: &[[f64; 4]], c: usize| load(&z[..L::N].iter().map(|r| r[c]).collect::<Vec<f64>>());
        let search =
            |z: &[[f64; 4]]| g.search(column(z, 0), column(z, 1), column(z, 2), column(z, 3));
        let (fa, fb) = (search(&a), search(&b));
        let (both_a, both_b) = g.land_both(fa, fb);
        let (one_a, one_b) = (g.land(fa), g.land(fb));
        let fields = |h: &LaneHit<L>| {
            [h.time, h.px, h.py, h.nx, h.ny, h.curvature, h.wall].map(|x| {
                let mut v = vec![0.0; L::N];
                x.store(&mut v);
                v.iter().map(|x| x.to_bits()).collect::<Vec<u64>>()
            })
        };
        assert_eq!(fields(&both_a), fields(&one_a), "pair {pair}, first");
        assert_eq!(fields(&both_b), fields(&one_b), "pair {pair}, second");
        if fb.wall.ne(fa.wall).any() {
            shared.1 += 1;
        } else {
            shared.0 += 1;
        }
    }
    shared
}

#[test]
fn landing_two_searches_at_once_is_landing_each() {
    let tables = [
        stadium(1.0),
        mushroom(1.0, 0.3, 1.0),
        mushroom(1.5, 0.4, 0.7),
    ];
    for t in &tables {
        let mut runs = vec![land_both_is_two_landings::<f64>(Baseline, t)];
        runs.push(land_both_is_two_landings::<
            <crate::lanes::Groups<1, 1, 1, 1> as crate::lanes::PerIsa>::Baseline,
        >(Baseline, t));
        #[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
        {
            if let Some(cpu) = crate::isa::Avx2Cpu::detect() {
                runs.push(land_both_is_two_landings::<crate::lanes::Avx2>(cpu, t));
            }
            if let Some(cpu) = crate::isa::Avx512Cpu::detect() {
                runs.push(land_both_is_two_landings::<crate::lanes::Avx512>(cpu, t));
            }
        }
        // Both ways through `land_both` were taken on every level.
        for (same, differing) in runs {
            assert!(
                same > 100 && differing > 100,
                "{same} shared, {differing} not"
            );
        }
    }
}

#[test]
fn a_table_mixing_axis_and_oblique_walls_casts_agree() {
    check_table(
        &split_triangle(),
        &[
            (d(0.0, 0.5), d(0.0, -1.0)),
            (d(0.9, 0.05), d(0.3, -1.0)),
            (d(0.0, 0.2), d(1.0, 1.0)),
        ],
    );
}

#[test]
fn stadium_of_segments_casts_agree_including_junctions() {
    for a in [1.0, 0.2, 4.0] {
        check_table(
            &stadium(a),
            &[
                (d(0.0, 0.0), d(a, 1.0)),
                (d(0.0, 0.0), d(-a, -1.0)),
                (d(0.0, 0.0), d(a, -1.0)),
                (d(0.0, 1.0), d(1.0, 0.0)),
                (d(0.0, 1.0 - 1e-12), d(1.0, 1e-13)),
                (d(a + 1.0, 0.0), d(0.0, 1.0)),
                (d(a + 1.0 - 1e-12, 0.0), d(0.0, 1.0)),
                (d(0.0, 0.0), d(1.0, 0.0)),
                (d(0.0, 0.0), d(0.0, 0.0)),
            ],
        );
    }
}

#[test]
fn sinai_of_segments_casts_agree_including_grazing_the_hole() {
    for (l, r) in [(2.0, 1.0), (1.0, 0.3)] {
        check_table(
            &sinai(l, r),
            &[
                (d(-l * 0.75, r), d(1.0, 0.0)),
                (d(-l * 0.75, r * (1.0 - 1e-12)), d(1.0, 0.0)),
                (d(-l * 0.75, r * (1.0 + 1e-12)), d(1.0, 0.0)),
                (d(0.0, r), d(0.0, 1.0)),
                (d(r, 0.0), d(0.0, 1.0)),
                (d(0.0, (l + r) / 2.0), d(0.0, -1.0)),
                (d(l * 0.75, l * 0.75), d(1.0, 1.0)),
                (d(-l * 0.75, l * 0.75), d(-1.0, 1.0)),
                (d(0.0, 0.0), d(0.0, 0.0)),
            ],
        );
    }
}

#[test]
fn mushroom_casts_agree_including_the_stem_corners() {
    let (r, w, h) = (1.0, 0.3, 1.0);
    check_table(
        &mushroom(r, w, h),
        &[
            (d(0.0, -0.5), d(0.0, 1.0)),
            // Into the re-entrant corners where the stem meets the cap's
            // floor, and along that floor.
            (d(0.0, -0.5), d(w, 0.5)),
            (d(0.0, -0.5), d(-w, 0.5)),
            (d(0.5, 0.0), d(-1.0, 0.0)),
            (d(0.5, 1e-12), d(-1.0, -1e-13)),
            (d(w, -0.5), d(0.0, 1.0)),
            (d(w * (1.0 - 1e-12), -0.5), d(0.0, 1.0)),
            // Grazing the cap, and out of the cap down the stem.
            (d(0.0, 1.0 - 1e-12), d(1.0, 0.0)),
            (d(0.0, 0.5), d(0.0, -1.0)),
            (d(0.9, 0.1), d(-1.0, -0.1)),
            // On the horizontal and vertical walls, with zeros of both
            // signs.
            (d(0.5, -0.0), d(-1.0, 0.5)),
            (d(0.5, 0.0), d(0.3, -1.0)),
            (d(0.5, -0.0), d(0.3, -1.0)),
            (d(-0.0, -h), d(0.2, 1.0)),
            (d(0.0, -h), d(-0.0, -1.0)),
            (d(w, -0.0), d(-1.0, -0.0)),
            (d(-w, -0.5), d(-1.0, 0.0)),
            (d(-w, -0.5), d(1.0, -0.0)),
        ],
    );
    // A cap of another radius (the general circle arithmetic).
    check_table(&mushroom(1.5, 0.4, 0.7), &[(d(0.0, -0.5), d(0.0, 1.0))]);
}

#[test]
fn l_shape_casts_agree_including_the_reflex_corner() {
    check_table(
        &l_shape(),
        &[
            (d(0.5, 0.5), d(0.5, 0.5)),
            (d(0.5, 0.5), d(1.5, -0.5)),
            (d(0.5, 1.5), d(1.0, 0.0)),
            (d(1.5, 0.5), d(0.0, 1.0)),
            (d(1.5, 1.0), d(-1.0, 0.0)),
            (d(1.0, 1.5), d(0.0, -1.0)),
            (d(0.0, 0.0), d(1.0, 1.0)),
        ],
    );
}

#[test]
fn twenty_gon_casts_agree_including_vertices() {
    let t = twenty_gon();
    let special: Vec<(DVec2, DVec2)> = t.walls().iter().map(|w| (DVec2::ZERO, w.start())).collect();
    check_table(&t, &special);
}

#[test]
fn convex_arcs_that_are_not_full_circles_agree() {
    // A square with a convex half-circle bulging in from its right wall
    // and a D-shaped hole: a convex half circle closed by its diameter,
    // so balls above the diameter are inside the arc's circle (the
    // convex cast then clamps at time 0 and normalises exactly).
    let t = SegmentTable::with_holes(
        vec![
            line(d(-2.0, -2.0), d(2.0, -2.0)),
            line(d(2.0, -2.0), d(2.0, -1.0)),
            arc(d(2.0, 0.0), 1.0, -FRAC_PI_2, -PI),
            line(d(2.0, 1.0), d(2.0, 2.0)),
            line(d(2.0, 2.0), d(-2.0, 2.0)),
            line(d(-2.0, 2.0), d(-2.0, -2.0)),
        ],
        vec![vec![
            arc(d(-0.8, 0.3), 0.5, 0.0, -PI),
            line(d(-1.3, 0.3), d(-0.3, 0.3)),
        ]],
    )
    .unwrap();
    check_table(
        &t,
        &[
            (d(0.0, 0.0), d(1.0, 0.0)),
            (d(0.0, 1.0), d(1.0, 0.0)),
            (d(-0.8, 0.5), d(0.0, -1.0)),
            (d(-0.8, 0.5), d(1.0, 0.0)),
            (d(-0.8, 0.31), d(0.3, -0.01)),
            (d(-0.8, -0.3), d(0.0, 1.0)),
        ],
    );
}

/// Operations per cast of the lane tables, counted (run with `--nocapture`).
mod counts {
    use std::f64::consts::TAU;

    use rand::{Rng, SeedableRng};
    use rand_pcg::Pcg64;
    use spinball_geometry::{Boundary, DVec2, Stadium};

    use super::super::*;
    use super::{alternating_twenty_gon, mushroom, stadium};
    use crate::geom::LaneStadium;
    use crate::lanes::counted::{Counted, take};

    fn per_cast<T: Boundary, G: Geom>(name: &str, t: &T, g: &G) -> [u64; 8] {
        const N: u64 = 10_000;
        let mut rng = Pcg64::seed_from_u64(3);
        take();
        for _ in 0..N {
            let o = t.sample_interior(&mut rng, 1.0);
            let v = DVec2::from_angle(rng.random::<f64>() * TAU);
            g.cast::<Counted>(Counted(o.x), Counted(o.y), Counted(v.x), Counted(v.y));
        }
        let c = take();
        let names = ["add", "mul", "div", "sqrt", "cmp", "select", "mask", "bits"];
        let per: Vec<String> = names
            .iter()
            .zip(c)
            .map(|(n, k)| format!("{n} {:.2}", k as f64 / N as f64))
            .collect();
        println!(
            "{name:<10} {:>6.1} per cast: {}",
            c.iter().sum::<u64>() as f64 / N as f64,
            per.join(", ")
        );
        c
    }

    #[test]
    fn operation_counts_per_cast() {
        let st = Stadium::new(1.0).unwrap();
        per_cast("stadium", &st, &LaneStadium::new(1.0));
        let seg = stadium(1.0);
        per_cast("stadium-seg", &seg, &LaneSegments::new(&seg).view::<true>());
        let m = mushroom(1.0, 0.3, 1.0);
        per_cast("mushroom", &m, &LaneSegments::new(&m).view::<true>());
        let g = alternating_twenty_gon();
        per_cast("20-gon", &g, &LaneSegments::new(&g).view::<false>());
    }
}
