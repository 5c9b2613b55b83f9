//! The escape kernel: balls on a table with holes, each run until it
//! reaches a hole or its budget (collisions or time) is spent.
//!
//! Escape runs are the one lane run whose trajectories end at different
//! steps, and escape times spread over orders of magnitude: a chunk of
//! lanes run until its longest-lived ball ends would idle most of its
//! lanes most of the time. So a lane whose ball ends — it reached a hole,
//! its time passed the budget, its collisions reached it, or it failed
//! where the scalar path fails — is **refilled** with the next initial
//! condition of the slice, and the run ends when the slice is used up and
//! the last ball ends (lanes left without a ball are masked: held, not
//! counted). Every lane steps as `Billiard::advance` does (cast, then
//! collide at a reflecting wall), so which lane runs a ball, and after
//! which other balls, changes nothing in its record.
//!
//! The closed-table kernels are untouched: this is a kernel of its own,
//! compiled only for tables built from segments (the only tables with
//! holes), at each instruction-set level.
//!
//! The kernel leaves a ball that escaped at the state it had before the
//! flight to the hole, with the time up to then; the caller replays that
//! last flight on the scalar path (`Billiard::advance`, one cast per
//! escaped ball) for the exit record, so where and how the ball left is
//! the scalar path's own answer, bitwise.

use spinball_core::State;

use super::{Kernel, five, mask_lane};
use crate::dynamics::{Balls, Law, Shell, ZeroRun, collide};
use crate::geom::Geom;
use crate::lanes::{Groups, Lanes, MAX_LANES, MaskOps};

/// Run each ball until it reaches one of `holes` or the budget is spent.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Escape<'a> {
    /// Most collisions per ball.
    pub collisions: u64,
    /// Longest time per ball (`f64::INFINITY`: none).
    pub time: f64,
    /// The hole walls' ids (as `f64`, as a hit carries its wall).
    pub holes: &'a [f64],
}

/// How one lane of an escape run ended.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Ended {
    /// A ball that escaped: the state it flew to the hole from; else the
    /// state after its last collision.
    pub state: State,
    /// A ball that escaped: the time up to its last collision; a censored
    /// one: the time it was last seen inside (the time budget, or the time
    /// of its last collision); NaN for a lane that failed.
    pub time: f64,
    /// Collisions taken.
    pub collisions: u64,
    /// Whether the ball reached a hole within the budget.
    pub escaped: bool,
}

impl Kernel for Escape<'_> {
    type In = State;
    type Out = Ended;
    /// Registers per group: AVX-512 2, AVX2 2, SSE2 2, portable `f64` 2.
    type Groups = Groups<2, 2, 2, 2>;
    /// As on the built-in tables.
    type BulkyGroups = <Self as Kernel>::Groups;
    /// As on the built-in tables.
    type ArcGroups = <Self as Kernel>::Groups;
    /// The lanes are refilled from the whole slice.
    const WHOLE: bool = true;

    #[inline(always)]
    fn chunk<G: Geom, L: Lanes>(
        &self,
        cpu: L::Needs,
        g: &G,
        law: &Law,
        ins: &[State],
        out: &mut Vec<Ended>,
    ) {
        let Some(&last) = ins.last() else {
            return;
        };
        let zero = L::splat(cpu, 0.0);
        let budget = L::splat(cpu, self.time);
        // Counts are exact in `f64` below 2⁵³ collisions (years of
        // running); a larger budget is never reached.
        let most = L::splat(cpu, self.collisions as f64);
        let mut parked = Parked::new(ins.len());
        let mut next = 0;
        for i in 0..L::N {
            match ins.get(next) {
                Some(s) => {
                    parked.start(i, next, s, law);
                    next += 1;
                }
                // No ball: a copy of the last, masked.
                None => parked.idle(i, &last, law),
            }
        }
        let (mut b, mut time, mut count, mut inv, mut zero_run, mut live) = parked.load::<L>(cpu);
        while live.any() {
            let hit = g.cast(b.x, b.y, b.vx, b.vy);
            zero_run.watch_where(hit.time, live);
            // `Billiard::advance`'s checks, in its order: a cast with no
            // wall or a non-finite hit, a stuck ball; then the time budget.
            let bad = hit
                .time
                .is_finite()
                .and(hit.px.is_finite())
                .and(hit.py.is_finite())
                .and(zero_run.moving())
                .not();
            let t = time + hit.time;
            let over = t.gt(budget).or(bad);
            let none = zero.ne(zero);
            let hole = self
                .holes
                .iter()
                .fold(none, |m, &h| m.or(hit.wall.eq(L::splat(cpu, h))));
            let bounce = live.and(over.or(hole).not());
            time = L::select(bounce, t, L::select(live.and(over), budget, time));
            count = L::select(bounce, count + 1.0, count);
            let mut after = b;
            collide(law, &mut after, hit, Shell::Fixed(inv));
            let (now, then) = (b.coords(), after.coords());
            b = Balls::new(five(|c| L::select(bounce, then[c], now[c])));
            let going = bounce.and(count.ge(most).not());
            let ending = live.and(going.not());
            if ending.any() {
                let failed = live.and(bad);
                let escaped = live.and(hole).and(over.not());
                parked.store(b, time, count, inv, &zero_run, going);
                for i in 0..L::N {
                    if !mask_lane::<L>(cpu, ending, i) {
                        continue;
                    }
                    parked.end(
                        i,
                        mask_lane::<L>(cpu, escaped, i),
                        mask_lane::<L>(cpu, failed, i),
                    );
                    if let Some(s) = ins.get(next) {
                        parked.start(i, next, s, law);
                        next += 1;
                    }
                }
                (b, time, count, inv, zero_run, live) = parked.load::<L>(cpu);
            } else {
                live = going;
            }
        }
        out.extend(parked.ended.into_iter().flatten());
    }

    fn is_sound(o: &Ended) -> bool {
        o.time.is_finite() && o.state.to_array().iter().all(|x| x.is_finite())
    }
}

/// The lanes of an escape run parked in memory, one array per quantity:
/// where balls are started and ended, between stretches of steps in
/// registers.
struct Parked {
    /// `(x, y, vx, vy, u)`.
    z: [[f64; MAX_LANES]; 5],
    time: [f64; MAX_LANES],
    count: [f64; MAX_LANES],
    /// `1/|V₀|²` of each ball's launch state.
    inv: [f64; MAX_LANES],
    zero_run: [f64; MAX_LANES],
    /// 1 where a ball runs, 0 where the lane is idle.
    live: [f64; MAX_LANES],
    /// The initial condition each lane runs.
    slot: [usize; MAX_LANES],
    /// The records so far, by initial condition.
    ended: Vec<Option<Ended>>,
}

impl Parked {
    fn new(n: usize) -> Self {
        Parked {
            z: [[0.0; MAX_LANES]; 5],
            time: [0.0; MAX_LANES],
            count: [0.0; MAX_LANES],
            inv: [0.0; MAX_LANES],
            zero_run: [0.0; MAX_LANES],
            live: [0.0; MAX_LANES],
            slot: [0; MAX_LANES],
            ended: vec![None; n],
        }
    }

    /// Put `s` (initial condition `index`) into lane `i`, launched as
    /// `Ball::new` launches it.
    #[inline(always)]
    fn start(&mut self, i: usize, index: usize, s: &State, law: &Law) {
        self.idle(i, s, law);
        self.live[i] = 1.0;
        self.slot[i] = index;
    }

    /// Hold `s` in lane `i`, masked.
    #[inline(always)]
    fn idle(&mut self, i: usize, s: &State, law: &Law) {
        for (zc, x) in self.z.iter_mut().zip(s.to_array()) {
            zc[i] = x;
        }
        // `Balls::inv_shell`, in one lane.
        self.inv[i] = 1.0 / law.norm2(s.velocity.x, s.velocity.y, s.spin);
        self.time[i] = 0.0;
        self.count[i] = 0.0;
        self.zero_run[i] = 0.0;
        self.live[i] = 0.0;
    }

    /// Record lane `i`'s ball as it stands.
    #[inline(always)]
    fn end(&mut self, i: usize, escaped: bool, failed: bool) {
        let state = State::from_array(self.z.map(|c| c[i]));
        self.ended[self.slot[i]] = Some(Ended {
            state,
            time: if failed { f64::NAN } else { self.time[i] },
            collisions: self.count[i] as u64,
            escaped,
        });
        self.live[i] = 0.0;
    }

    /// The registers into memory; `live` are the lanes still running.
    #[inline(always)]
    fn store<L: Lanes>(
        &mut self,
        b: Balls<L>,
        time: L,
        count: L,
        inv: L,
        zero_run: &ZeroRun<L>,
        live: L::Mask,
    ) {
        for (c, zc) in b.coords().into_iter().zip(self.z.iter_mut()) {
            c.store(zc);
        }
        time.store(&mut self.time);
        count.store(&mut self.count);
        inv.store(&mut self.inv);
        zero_run.runs().store(&mut self.zero_run);
        let cpu = time.proof();
        L::select(live, L::splat(cpu, 1.0), L::splat(cpu, 0.0)).store(&mut self.live);
    }

    /// Memory into registers. No lane is stuck here: a stuck ball ends
    /// in the step it gets stuck.
    #[allow(clippy::type_complexity)]
    #[inline(always)]
    fn load<L: Lanes>(&self, cpu: L::Needs) -> (Balls<L>, L, L, L, ZeroRun<L>, L::Mask) {
        (
            Balls::new(five(|c| L::load(cpu, &self.z[c]))),
            L::load(cpu, &self.time),
            L::load(cpu, &self.count),
            L::load(cpu, &self.inv),
            ZeroRun::resume(L::load(cpu, &self.zero_run)),
            L::load(cpu, &self.live).gt(L::splat(cpu, 0.0)),
        )
    }
}
