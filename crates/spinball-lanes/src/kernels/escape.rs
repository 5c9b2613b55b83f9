//! The escape kernel: balls on a table with holes, each run until it
//! reaches a hole or its budget (collisions or time) is spent.
//!
//! Escape runs are the one lane run whose trajectories end at different
//! steps. Every lane steps as the plain kernel does (`Billiard::advance`:
//! cast, then collide at a reflecting wall), and a lane that ends — its
//! ball reached a hole, its time passed the budget, or it failed where the
//! scalar path fails — is **masked**: its state, time and collision count
//! are held from then on, and the chunk ends when no lane is left running
//! (or at the collision budget). The closed-table kernels are untouched:
//! this is a kernel of its own, compiled only for tables built from
//! segments (the only tables with holes), at each instruction-set level.
//!
//! The kernel leaves a ball that escaped at the state it had before the
//! flight to the hole, with the time up to then; the caller replays that
//! last flight on the scalar path (`Billiard::advance`, one cast per
//! escaped ball) for the exit record, so where and how the ball left is
//! the scalar path's own answer, bitwise.

use spinball_core::State;

use super::{Kernel, five, load_states, mask_lane, state_of};
use crate::dynamics::{Balls, Law, Shell, ZeroRun, collide};
use crate::geom::Geom;
use crate::lanes::{Groups, Lanes, MaskOps};

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
    /// Registers per group: AVX-512 2, AVX2 2, SSE2 2, portable `f64` 2. A
    /// chunk lasts as long as its longest-lived ball, so wider groups idle
    /// more of their lanes.
    type Groups = Groups<2, 2, 2, 2>;
    /// As on the built-in tables.
    type BulkyGroups = <Self as Kernel>::Groups;
    /// As on the built-in tables.
    type ArcGroups = <Self as Kernel>::Groups;

    #[inline(always)]
    fn chunk<G: Geom, L: Lanes>(
        &self,
        cpu: L::Needs,
        g: &G,
        law: &Law,
        ins: &[State],
        out: &mut Vec<Ended>,
    ) {
        let zero = L::splat(cpu, 0.0);
        let none = zero.ne(zero);
        let budget = L::splat(cpu, self.time);
        let mut b = Balls::new(load_states::<L>(cpu, |i| ins[i]));
        let shell = Shell::Fixed(b.inv_shell(law));
        let mut time = zero;
        let mut count = zero;
        let mut zero_run = ZeroRun::new(cpu);
        // Lanes still running, and lanes that ended at a hole.
        let mut live = zero.eq(zero);
        let mut escaped = none;
        let mut failed = none;
        for _ in 0..self.collisions {
            if !live.any() {
                break;
            }
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
            let hole = self
                .holes
                .iter()
                .fold(none, |m, &h| m.or(hit.wall.eq(L::splat(cpu, h))));
            let bounce = live.and(over.or(hole).not());
            failed = failed.or(live.and(bad));
            escaped = escaped.or(live.and(hole).and(over.not()));
            time = L::select(bounce, t, L::select(live.and(over), budget, time));
            count = L::select(bounce, count + 1.0, count);
            let mut next = b;
            collide(law, &mut next, hit, shell);
            let (now, then) = (b.coords(), next.coords());
            b = Balls::new(five(|c| L::select(bounce, then[c], now[c])));
            live = bounce;
        }
        let time = L::select(failed, L::splat(cpu, f64::NAN), time);
        let z = b.coords();
        out.extend((0..L::N).map(|i| Ended {
            state: state_of(&z, i),
            time: time.lane(i),
            collisions: count.lane(i) as u64,
            escaped: mask_lane::<L>(cpu, escaped, i),
        }));
    }

    fn is_sound(o: &Ended) -> bool {
        o.time.is_finite() && o.state.to_array().iter().all(|x| x.is_finite())
    }
}
