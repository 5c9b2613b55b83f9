//! The public entry point, [`LaneBilliard`]: a table, a spin law, an
//! instruction set and a thread count, and one method per kernel.
//!
//! It exists so that callers (the ensemble engine of `spinball-analysis`,
//! or anyone with a slice of initial conditions) see a safe, slice-in,
//! outcomes-out API: it checks the inputs as the scalar path does, picks the
//! concrete table and the instruction set once, splits the work over
//! threads, and turns a trajectory that went non-finite into an error naming
//! its initial condition.

use spinball_core::perturbation::check_delta0;
use spinball_core::{
    Ball, Billiard, Event, MAX_QR_INTERVAL, Perturbation, SpinLaw, State, TangentVector, Units,
};
use spinball_geometry::{Boundary, SegmentTable, Shape, Table, WallKind};

use crate::dispatch::Dispatch;
use crate::dynamics::Law;
use crate::error::LanesError;
use crate::geom::{Geom, LaneCircle, LaneRectangle, LaneSegments, LaneSinai, LaneStadium};
use crate::isa::Isa;
use crate::kernels::{self, Kernel};
use crate::outcome::{Escape, Flight, SpectrumStretch, Stretch};
use crate::paused::{Partner, Paused};

/// A multiple of every kernel's lane count on every level (32, 24, 16, 12,
/// 8 trajectories). Callers that split an ensemble into chunks (and
/// [`LaneBilliard::with_threads`]) should cut at multiples of it: then only
/// the last chunk of a run has lanes idling in a partial register group.
/// (Any split gives the same numbers; this is about speed only.)
pub const CHUNK: usize = 96;

/// A spinning billiard whose ensembles run in vector lanes.
///
/// Holds a table with a lane form (any table whose [`Boundary::shape`] is
/// `Some`: the built-in `Circle`, `Rectangle`, `Stadium`, `Sinai`, the
/// [`Table`] enum, a `SegmentTable`, or a reference to one), a [`SpinLaw`],
/// the instruction-set level
/// ([`Isa::detect`] unless set) and a thread count (1 unless set). Every
/// method takes a slice of initial conditions of any length and returns one
/// outcome per initial condition, **in input order**; an outcome depends only
/// on its own initial condition (not on the slice, the level, the lane count
/// or the threads).
///
/// A table with holes is taken by [`new_open`](Self::new_open), for
/// [`escape_times`](Self::escape_times) only.
///
/// ```
/// use spinball_core::{Billiard, SpinLaw, State};
/// use spinball_geometry::{DVec2, Stadium};
/// use spinball_lanes::LaneBilliard;
///
/// let law = SpinLaw::new(0.5)?;
/// let lanes = LaneBilliard::new(Stadium::new(1.0)?, law)?;
/// let starts: Vec<State> = (0..10)
///     .map(|i| State::new(DVec2::new(0.1 * i as f64 - 0.5, 0.2), DVec2::new(0.6, 0.7), 0.3))
///     .collect();
/// let flights = lanes.trajectories(&starts, 1000)?;
///
/// // Bitwise the scalar collision map, lane by lane.
/// let scalar = Billiard::new(Stadium::new(1.0)?, law);
/// let mut ball = scalar.launch(starts[3])?;
/// for _ in 0..1000 {
///     scalar.step(&mut ball)?;
/// }
/// assert_eq!(flights[3].end, *ball.state());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct LaneBilliard<B = Table> {
    table: B,
    runner: Runner,
}

/// Everything a run needs apart from the table's Rust type: the kernels
/// are compiled here, once, in this crate, whatever table type a caller
/// uses (a `LaneBilliard<B>` only checks the starts with `B`).
#[derive(Debug, Clone, PartialEq)]
struct Runner {
    shape: Shape,
    /// The walls of a [`Shape::Segments`] compiled for the kernels (once,
    /// here, rather than on every run).
    segments: Option<LaneSegments>,
    /// The ids of the hole walls (as `f64`, as the kernels carry wall ids);
    /// empty for a closed table. Only [`LaneBilliard::new_open`] makes a
    /// runner with holes, and only the escape kernel runs one.
    holes: Vec<f64>,
    law: SpinLaw,
    isa: Isa,
    threads: usize,
}

/// Whether `table` can run in lanes: it has a [`Shape`] the kernels compile.
/// Every built-in table and every closed `SegmentTable` can; a table with
/// holes or periodic walls cannot (it runs on the scalar path; escape from
/// holes runs in lanes, see [`has_escape_lane_form`]).
#[must_use]
pub fn has_lane_form<B: Boundary + ?Sized>(table: &B) -> bool {
    table.shape().is_some_and(|s| s.is_closed())
}

/// Whether [`LaneBilliard::escape_times`] runs `table` in lanes: a table
/// built from segments (a `SegmentTable`, the only tables with holes)
/// whose walls reflect or are holes. Periodic walls run on the scalar path.
#[must_use]
pub fn has_escape_lane_form<B: Boundary + ?Sized>(table: &B) -> bool {
    table.shape().is_some_and(|s| escape_form(&s))
}

/// A table built from segments without periodic walls.
fn escape_form(shape: &Shape) -> bool {
    match shape {
        Shape::Segments { kinds, .. } => !kinds.iter().any(WallKind::is_periodic),
        _ => false,
    }
}

impl<B: Boundary> LaneBilliard<B> {
    /// `table` and `law`, at the fastest instruction set of this CPU, on one
    /// thread.
    ///
    /// # Errors
    /// [`LanesError::NoLaneForm`] for a table without a [`Shape`], and
    /// [`LanesError::OpenTable`] for a table with holes or periodic walls
    /// (run them on the scalar path).
    pub fn new(table: B, law: SpinLaw) -> Result<Self, LanesError> {
        let shape = table.shape().ok_or(LanesError::NoLaneForm)?;
        if !shape.is_closed() {
            return Err(LanesError::OpenTable);
        }
        Self::build(table, shape, law)
    }

    /// `table` and `law` for [`escape_times`](Self::escape_times): a table
    /// built from segments whose walls reflect or are holes (closed ones
    /// too). The other kernels refuse a table with holes
    /// ([`LanesError::OpenTable`]).
    ///
    /// # Errors
    /// [`LanesError::NoLaneForm`] for a table without a [`Shape`], and
    /// [`LanesError::NoEscapeForm`] for one not built from segments or with
    /// periodic walls (run those on the scalar path).
    pub fn new_open(table: B, law: SpinLaw) -> Result<Self, LanesError> {
        let shape = table.shape().ok_or(LanesError::NoLaneForm)?;
        if !escape_form(&shape) {
            return Err(LanesError::NoEscapeForm {
                shape: shape.to_string(),
            });
        }
        Self::build(table, shape, law)
    }

    fn build(table: B, shape: Shape, law: SpinLaw) -> Result<Self, LanesError> {
        let holes = match &shape {
            Shape::Segments { kinds, .. } => kinds
                .iter()
                .enumerate()
                .filter(|(_, k)| k.is_hole())
                .map(|(id, _)| id as f64)
                .collect(),
            _ => Vec::new(),
        };
        let segments = match &shape {
            // The walls of a `SegmentTable` make a valid one again; loops
            // that do not (a hand-made shape) have no lane form.
            Shape::Segments { outer, holes, .. } => Some(LaneSegments::new(
                &SegmentTable::with_holes(outer.clone(), holes.clone())
                    .map_err(|_| LanesError::NoLaneForm)?,
            )),
            _ => None,
        };
        Ok(LaneBilliard {
            table,
            runner: Runner {
                shape,
                segments,
                holes,
                law,
                isa: Isa::detect(),
                threads: 1,
            },
        })
    }

    /// Use instruction-set level `isa` (for tests and benchmarks; results do
    /// not depend on it).
    ///
    /// # Errors
    /// [`LanesError::IsaUnavailable`] if this CPU cannot run it.
    pub fn with_isa(mut self, isa: Isa) -> Result<Self, LanesError> {
        self.runner.isa = isa.checked()?;
        Ok(self)
    }

    /// Split every run into `threads` contiguous parts run on scoped threads
    /// (results do not depend on it).
    ///
    /// # Errors
    /// [`LanesError::InvalidOption`] for 0.
    pub fn with_threads(mut self, threads: usize) -> Result<Self, LanesError> {
        if threads == 0 {
            return Err(LanesError::invalid("threads", "must be at least 1"));
        }
        self.runner.threads = threads;
        Ok(self)
    }

    /// The table.
    pub fn table(&self) -> &B {
        &self.table
    }
    /// The table's lane form.
    pub fn shape(&self) -> &Shape {
        &self.runner.shape
    }
    /// The spin law.
    pub fn law(&self) -> &SpinLaw {
        &self.runner.law
    }
    /// The instruction-set level the kernels run at.
    pub fn isa(&self) -> Isa {
        self.runner.isa
    }
    /// Threads per run.
    pub fn threads(&self) -> usize {
        self.runner.threads
    }

    /// `collisions` steps of the collision map from each start: the end
    /// state is bitwise `Billiard::step`'s, the time is the same sum.
    ///
    /// # Errors
    /// [`LanesError::Launch`] for a start `Billiard::launch` rejects,
    /// [`LanesError::NonFinite`] for a trajectory the scalar path fails on.
    pub fn trajectories(
        &self,
        starts: &[State],
        collisions: u64,
    ) -> Result<Vec<Flight>, LanesError> {
        self.check_starts(starts)?;
        self.runner.plain(starts, collisions)
    }

    /// The largest Lyapunov exponent by the paper's finite-difference
    /// Benettin method, `δ0 = delta0` in the units of
    /// [`Perturbation`] (the table's unit length and each ball's speed, as
    /// powers of two: exactly `delta0` on the paper's tables), shadow along
    /// `directions[i]` (a unit 5-vector, as
    /// `spinball_core::random_direction` draws).
    ///
    /// The reference and shadow trajectories are bitwise the scalar ones;
    /// `Σ ln(δ/δ0)` differs from the scalar `largest_lyapunov` by rounding in
    /// the product of the factors only (relative `~1e-13`; see the crate docs).
    ///
    /// # Errors
    /// [`LanesError::InvalidOption`] for zero collisions, `delta0` outside
    /// `[1e-11, 1e-3]`, mismatched lengths or a zero or non-finite direction;
    /// [`LanesError::Launch`]; [`LanesError::Perturbation`] where the
    /// scalar `Perturbation::new` fails; [`LanesError::NonFinite`] (e.g. a
    /// shadow that lands exactly on the reference, or a stuck ball).
    pub fn lyapunov_fd(
        &self,
        starts: &[State],
        directions: &[TangentVector],
        delta0: f64,
        collisions: u64,
    ) -> Result<Vec<Stretch>, LanesError> {
        check_collisions(collisions)?;
        let launched = self.start_fd(starts, directions, delta0)?;
        Ok(self
            .resume(&launched, collisions)?
            .iter()
            .map(Paused::stretch)
            .collect())
    }

    /// The largest Lyapunov exponent by exact tangent dynamics, starting from
    /// `directions[i]`.
    ///
    /// The reference trajectory and the tangent map are bitwise the scalar
    /// ones (`Billiard::step_tangent`); the vector is rescaled by exact powers
    /// of two every 8 collisions instead of normalised every collision, so
    /// `Σ ln` agrees with the scalar `largest_lyapunov` to rounding, not
    /// bitwise (see the crate docs for how closely).
    ///
    /// # Errors
    /// As [`lyapunov_fd`](Self::lyapunov_fd), without `delta0`.
    pub fn lyapunov_tangent(
        &self,
        starts: &[State],
        directions: &[TangentVector],
        collisions: u64,
    ) -> Result<Vec<Stretch>, LanesError> {
        check_collisions(collisions)?;
        let launched = self.start_tangent(starts, directions)?;
        Ok(self
            .resume(&launched, collisions)?
            .iter()
            .map(Paused::stretch)
            .collect())
    }

    /// The trajectories of [`lyapunov_fd`](Self::lyapunov_fd) before their
    /// first collision, to be run in legs with [`resume`](Self::resume).
    ///
    /// # Errors
    /// As [`lyapunov_fd`](Self::lyapunov_fd), without the run's errors.
    pub fn start_fd(
        &self,
        starts: &[State],
        directions: &[TangentVector],
        delta0: f64,
    ) -> Result<Vec<Paused>, LanesError> {
        check_delta0(delta0).map_err(|e| LanesError::invalid("delta0", e.to_string()))?;
        let ins = self.check_lcn(starts, directions)?;
        ins.iter()
            .enumerate()
            .map(|(index, (s, d))| {
                let p = Perturbation::new(&self.table, s, &self.runner.law, delta0)
                    .map_err(|source| LanesError::Perturbation { index, source })?;
                // The shadow as the scalar launches it (`Perturbation::offset`'s
                // products and sums, in the kernels' order).
                let (z, d, scaled) = (s.to_array(), d.to_array(), p.scaled());
                let shadow = std::array::from_fn(|c| z[c] + d[c] * scaled[c]);
                Ok(Paused::launched(*s, shadow, Partner::Shadow { delta0 }))
            })
            .collect()
    }

    /// The trajectories of [`lyapunov_tangent`](Self::lyapunov_tangent)
    /// before their first collision, to be run in legs with
    /// [`resume`](Self::resume).
    ///
    /// # Errors
    /// As [`lyapunov_tangent`](Self::lyapunov_tangent), without the run's
    /// errors.
    pub fn start_tangent(
        &self,
        starts: &[State],
        directions: &[TangentVector],
    ) -> Result<Vec<Paused>, LanesError> {
        let ins = self.check_lcn(starts, directions)?;
        Ok(ins
            .iter()
            .map(|(s, d)| {
                let from = Units::new(&self.table, s, &self.runner.law).measure(d);
                Paused::launched(*s, d.to_array(), Partner::Tangent { from })
            })
            .collect())
    }

    /// `collisions` more collisions of each paused trajectory (all of one
    /// method: all from [`start_fd`](Self::start_fd) with the same `delta0`,
    /// or all from [`start_tangent`](Self::start_tangent)), in input order.
    ///
    /// Bitwise as if the trajectory had never stopped: `T_0` collisions then
    /// `T_1 − T_0` more give the same [`Paused::stretch`] as `T_1` at once,
    /// on every instruction set.
    ///
    /// # Errors
    /// [`LanesError::InvalidOption`] for zero collisions or trajectories of
    /// different methods; [`LanesError::Perturbation`] for a finite-difference
    /// launch state `Perturbation::new` rejects; [`LanesError::NonFinite`]
    /// for a trajectory that became non-finite (its whole run so far is what
    /// the scalar path would fail on).
    pub fn resume(&self, paused: &[Paused], collisions: u64) -> Result<Vec<Paused>, LanesError> {
        check_collisions(collisions)?;
        let Some(first) = paused.first() else {
            return Ok(Vec::new());
        };
        if let Some(other) = paused.iter().find(|p| !same_kernel(&p.kind, &first.kind)) {
            return Err(LanesError::invalid(
                "paused",
                format!(
                    "one resume runs one method: got {:?} and {:?}",
                    first.kind, other.kind
                ),
            ));
        }
        let law = &self.runner.law;
        match first.kind {
            Partner::Shadow { delta0 } => {
                let perturbations = paused
                    .iter()
                    .enumerate()
                    .map(|(index, p)| {
                        Perturbation::new(&self.table, &p.launch, law, delta0)
                            .map_err(|source| LanesError::Perturbation { index, source })
                    })
                    .collect::<Result<Vec<_>, _>>()?;
                by_key(&perturbations, paused, |part, p| {
                    self.runner.finite_difference(part, p, collisions)
                })
            }
            Partner::Tangent { .. } => {
                let units: Vec<Units> = paused
                    .iter()
                    .map(|p| Units::new(&self.table, &p.launch, law))
                    .collect();
                by_key(&units, paused, |part, u| {
                    self.runner.tangent(part, u, collisions)
                })
            }
        }
    }

    /// The Lyapunov spectrum by exact tangent dynamics: five vectors from
    /// `frames[i]` (orthonormal, as the scalar `lyapunov_spectrum` draws),
    /// modified Gram–Schmidt every `qr_interval` collisions and after the
    /// last.
    ///
    /// # Errors
    /// [`LanesError::InvalidOption`] for zero collisions, `qr_interval`
    /// outside `1..=`[`MAX_QR_INTERVAL`], mismatched lengths or a zero or
    /// non-finite vector; [`LanesError::Launch`]; [`LanesError::NonFinite`].
    pub fn spectrum(
        &self,
        starts: &[State],
        frames: &[[TangentVector; 5]],
        collisions: u64,
        qr_interval: u32,
    ) -> Result<Vec<SpectrumStretch>, LanesError> {
        if !(1..=MAX_QR_INTERVAL).contains(&qr_interval) {
            return Err(LanesError::invalid(
                "qr_interval",
                format!("must be in 1..={MAX_QR_INTERVAL}, got {qr_interval}"),
            ));
        }
        check_collisions(collisions)?;
        check_lengths(starts.len(), frames.len())?;
        self.check_starts(starts)?;
        for f in frames {
            for v in f {
                check_vector(v)?;
            }
        }
        let ins: Vec<_> = starts.iter().copied().zip(frames.iter().copied()).collect();
        self.runner.spectrum(&ins, collisions, qr_interval)
    }

    /// Run each start until its ball reaches a hole or the budget is spent:
    /// at most `collisions` collisions and time `time` (`f64::INFINITY`: no
    /// time limit). One [`Escape`] per start, in input order; a ball still
    /// inside at the budget is censored, never dropped.
    ///
    /// Bitwise what the scalar path records running `Billiard::advance`
    /// until an escape or the budget (as `spinball-analysis`'s
    /// `OpenEnsemble::escape_times`): the same escape time, collision count
    /// and exit (the ball's last flight to the hole is replayed by
    /// `Billiard::advance` itself). A lane whose ball ends takes the next
    /// start, so the lanes stay busy however unequal the escape times;
    /// collision budgets above `2⁵³` (never reached) count as unlimited.
    ///
    /// # Errors
    /// [`LanesError::InvalidOption`] for zero collisions or a time that is
    /// not positive; [`LanesError::NoEscapeForm`] for a table not built from
    /// segments; [`LanesError::Launch`]; [`LanesError::NonFinite`] where the
    /// scalar path fails (no wall ahead, a stuck ball).
    pub fn escape_times(
        &self,
        starts: &[State],
        collisions: u64,
        time: f64,
    ) -> Result<Vec<Escape>, LanesError> {
        check_collisions(collisions)?;
        if !(time > 0.0) {
            return Err(LanesError::invalid(
                "time",
                format!("the time budget must be > 0 (or infinite), got {time}"),
            ));
        }
        if !escape_form(&self.runner.shape) {
            return Err(LanesError::NoEscapeForm {
                shape: self.runner.shape.to_string(),
            });
        }
        self.check_starts(starts)?;
        let ended = self.runner.escape(starts, collisions, time)?;
        let billiard = Billiard::new(&self.table, self.runner.law);
        ended
            .iter()
            .enumerate()
            .map(|(index, e)| {
                if !e.escaped {
                    return Ok(Escape {
                        time: e.time,
                        collisions: e.collisions,
                        exit: None,
                    });
                }
                // The last flight, on the scalar path: the lanes found the
                // same hole (bitwise the scalar cast); a disagreement is
                // reported as a failure the scalar rerun explains.
                let mut ball = Ball::new(e.state, &self.runner.law)
                    .map_err(|_| LanesError::NonFinite { index })?;
                match billiard.advance(&mut ball) {
                    Ok(Event::Escape(exit)) => Ok(Escape {
                        time: e.time + exit.time,
                        collisions: e.collisions,
                        exit: Some(exit),
                    }),
                    _ => Err(LanesError::NonFinite { index }),
                }
            })
            .collect()
    }

    fn check_starts(&self, starts: &[State]) -> Result<(), LanesError> {
        let billiard = Billiard::new(&self.table, self.runner.law);
        for (index, s) in starts.iter().enumerate() {
            billiard
                .launch(*s)
                .map_err(|source| LanesError::Launch { index, source })?;
        }
        Ok(())
    }

    fn check_lcn(
        &self,
        starts: &[State],
        directions: &[TangentVector],
    ) -> Result<Vec<(State, TangentVector)>, LanesError> {
        self.runner.closed()?;
        check_lengths(starts.len(), directions.len())?;
        self.check_starts(starts)?;
        for d in directions {
            check_vector(d)?;
        }
        Ok(starts
            .iter()
            .copied()
            .zip(directions.iter().copied())
            .collect())
    }
}

/// Run `ins` in groups of equal `keys[i]` (the units of a start: on the
/// samplers' energy shell all of them are equal), outcomes back in input
/// order and a failing lane's index made absolute.
fn by_key<K: PartialEq + Copy, I: Copy, O>(
    keys: &[K],
    ins: &[I],
    mut run: impl FnMut(&[I], &K) -> Result<Vec<O>, LanesError>,
) -> Result<Vec<O>, LanesError> {
    let mut out: Vec<Option<O>> = (0..ins.len()).map(|_| None).collect();
    let mut todo: Vec<usize> = (0..ins.len()).collect();
    while let Some(&first) = todo.first() {
        let key = keys[first];
        let (group, rest): (Vec<usize>, Vec<usize>) =
            todo.into_iter().partition(|&i| keys[i] == key);
        let part: Vec<I> = group.iter().map(|&i| ins[i]).collect();
        let got = run(&part, &key).map_err(|e| match e {
            LanesError::NonFinite { index } => LanesError::NonFinite {
                index: group[index],
            },
            other => other,
        })?;
        for (&i, o) in group.iter().zip(got) {
            out[i] = Some(o);
        }
        todo = rest;
    }
    Ok(out.into_iter().flatten().collect())
}

impl Runner {
    // Not generic and not inlined: each kernel is compiled once, here.
    fn plain(&self, ins: &[State], collisions: u64) -> Result<Vec<Flight>, LanesError> {
        self.run(&kernels::Plain { collisions }, ins)
    }

    fn finite_difference(
        &self,
        ins: &[Paused],
        p: &Perturbation,
        collisions: u64,
    ) -> Result<Vec<Paused>, LanesError> {
        let k = kernels::FiniteDifference {
            collisions,
            delta0: p.delta0(),
            inv_units: p.inv_units(),
        };
        self.run(&k, ins)
    }

    fn tangent(
        &self,
        ins: &[Paused],
        units: &Units,
        collisions: u64,
    ) -> Result<Vec<Paused>, LanesError> {
        let k = kernels::Tangent {
            collisions,
            units: *units,
        };
        self.run(&k, ins)
    }

    fn spectrum(
        &self,
        ins: &[(State, [TangentVector; 5])],
        collisions: u64,
        qr_interval: u32,
    ) -> Result<Vec<SpectrumStretch>, LanesError> {
        let k = kernels::Spectrum {
            collisions,
            qr_interval: u64::from(qr_interval),
        };
        self.run(&k, ins)
    }

    fn escape(
        &self,
        ins: &[State],
        collisions: u64,
        time: f64,
    ) -> Result<Vec<kernels::Ended>, LanesError> {
        let k = kernels::Escape {
            collisions,
            time,
            holes: &self.holes,
        };
        // Only the curved view: on a table without arcs it finds the same
        // hits (the flat walls win every comparison), and one copy per
        // level keeps the crate's compile time down.
        let Some(s) = &self.segments else {
            return Err(LanesError::NoLaneForm);
        };
        sound::<kernels::Escape>(self.split(&k, &s.view::<true>(), &Law::new(&self.law), ins))
    }

    /// The λ kernels run closed tables only.
    fn closed(&self) -> Result<(), LanesError> {
        if self.holes.is_empty() {
            Ok(())
        } else {
            Err(LanesError::OpenTable)
        }
    }

    /// Dispatch once on the table, split over threads, check the outcomes.
    fn run<K: Kernel>(&self, k: &K, ins: &[K::In]) -> Result<Vec<K::Out>, LanesError> {
        self.closed()?;
        let law = Law::new(&self.law);
        let out = match &self.shape {
            Shape::Circle { radius } => self.split(k, &LaneCircle::new(*radius), &law, ins),
            Shape::Rectangle { l, h } => self.split(k, &LaneRectangle::new(*l, *h), &law, ins),
            Shape::Stadium { a } => self.split(k, &LaneStadium::new(*a), &law, ins),
            Shape::Sinai { l, r } => self.split(k, &LaneSinai::new(*l, *r), &law, ins),
            Shape::Segments { .. } => match &self.segments {
                Some(s) if s.is_curved() => self.split(k, &s.view::<true>(), &law, ins),
                Some(s) => self.split(k, &s.view::<false>(), &law, ins),
                None => return Err(LanesError::NoLaneForm),
            },
        };
        sound::<K>(out)
    }

    fn split<K: Kernel, G: Geom>(&self, k: &K, g: &G, law: &Law, ins: &[K::In]) -> Vec<K::Out> {
        let isa = self.isa;
        if self.threads <= 1 || ins.len() <= CHUNK {
            return k.dispatch(isa, g, law, ins);
        }
        // Parts of whole chunks, so only the last part has a tail.
        let per = ins.len().div_ceil(self.threads).div_ceil(CHUNK) * CHUNK;
        std::thread::scope(|s| {
            let parts: Vec<_> = ins
                .chunks(per)
                .map(|part| s.spawn(move || k.dispatch(isa, g, law, part)))
                .collect();
            parts
                .into_iter()
                .flat_map(|h| h.join().unwrap_or_else(|e| std::panic::resume_unwind(e)))
                .collect()
        })
    }
}

/// The outcomes, or the first that is not sound as an error.
fn sound<K: Kernel>(out: Vec<K::Out>) -> Result<Vec<K::Out>, LanesError> {
    match out.iter().position(|o| !K::is_sound(o)) {
        Some(index) => Err(LanesError::NonFinite { index }),
        None => Ok(out),
    }
}

/// Whether two paused trajectories run on the same kernel with the same
/// constants.
fn same_kernel(a: &Partner, b: &Partner) -> bool {
    match (a, b) {
        (Partner::Shadow { delta0: x }, Partner::Shadow { delta0: y }) => x == y,
        (Partner::Tangent { .. }, Partner::Tangent { .. }) => true,
        _ => false,
    }
}

fn check_collisions(collisions: u64) -> Result<(), LanesError> {
    if collisions == 0 {
        return Err(LanesError::invalid("collisions", "must be > 0"));
    }
    Ok(())
}

fn check_lengths(starts: usize, vectors: usize) -> Result<(), LanesError> {
    if starts != vectors {
        return Err(LanesError::invalid(
            "directions",
            format!("{vectors} directions for {starts} initial conditions"),
        ));
    }
    Ok(())
}

fn check_vector(v: &TangentVector) -> Result<(), LanesError> {
    let z = v.to_array();
    if !(z.iter().all(|x| x.is_finite()) && v.norm() > 0.0) {
        return Err(LanesError::invalid(
            "directions",
            format!("tangent vectors must be finite and non-zero, got {z:?}"),
        ));
    }
    Ok(())
}
