//! The collision map: a table and a spin law, stepping a ball from wall to wall.

use glam::DVec2;
use spinball_geometry::{Boundary, Hit};

use crate::collision::Collision;
use crate::error::{LaunchError, StepError};
use crate::event::{Crossing, Event, Exit};
use crate::observer::Observer;
use crate::spin_law::SpinLaw;
use crate::state::{Ball, State};
use crate::stuck::watch_zero_time;
use crate::tangent::{Jacobian, TangentFrame, TangentVector};
use spinball_geometry::WallKind;

/// A spinning billiard: a table `B` and a [`SpinLaw`]. Generic over the table
/// so every step is statically dispatched and allocation-free.
///
/// ```
/// use spinball_core::{Billiard, SpinLaw, State};
/// use spinball_geometry::{DVec2, Stadium};
///
/// let billiard = Billiard::new(Stadium::new(1.0)?, SpinLaw::new(0.5)?);
/// let mut ball = billiard.launch(State::new(DVec2::ZERO, DVec2::new(0.6, 0.7), 0.3))?;
/// let e0 = billiard.energy(ball.state());
/// for _ in 0..1000 {
///     let c = billiard.step(&mut ball)?;
///     assert!((c.q - c.q_after(0.5)).abs() < 1e-14); // Q survives each collision
/// }
/// assert!((billiard.energy(ball.state()) - e0).abs() < 1e-15);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Billiard<B> {
    table: B,
    law: SpinLaw,
}

/// Totals of a run of collisions.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Run {
    /// Collisions taken.
    pub collisions: u64,
    /// Total flight time.
    pub time: f64,
}

impl<B: Boundary> Billiard<B> {
    /// A billiard on `table` with collision law `law`.
    pub fn new(table: B, law: SpinLaw) -> Self {
        Billiard { table, law }
    }

    /// The table.
    pub fn table(&self) -> &B {
        &self.table
    }
    /// The spin law.
    pub fn law(&self) -> &SpinLaw {
        &self.law
    }

    /// Energy of a state (paper eq. 4).
    pub fn energy(&self, state: &State) -> f64 {
        state.energy(&self.law)
    }

    /// A ball in `state`, checked: finite, moving, inside the table.
    ///
    /// # Errors
    /// [`LaunchError`].
    pub fn launch(&self, state: State) -> Result<Ball, LaunchError> {
        let ball = Ball::new(state, &self.law)?;
        if !self.table.contains(state.position) {
            return Err(LaunchError::Outside(state.position));
        }
        Ok(ball)
    }

    #[inline]
    fn next_hit(&self, s: &State) -> Result<Hit, StepError> {
        let hit = self
            .table
            .cast(s.position, s.velocity)
            .ok_or(StepError::NoWall {
                position: s.position,
                velocity: s.velocity,
            })?;
        if hit.time.is_finite() && hit.point.is_finite() {
            Ok(hit)
        } else {
            Err(StepError::NonFinite {
                position: s.position,
            })
        }
    }

    /// The next reflecting wall: the cast's hit on a closed table (the one
    /// test of its kind, a constant for the built-in tables, is all this
    /// adds to a step); on an open table, the flight through periodic
    /// walls to it (time summed), or [`StepError::Escaped`].
    #[inline]
    fn fly(&self, ball: &mut Ball) -> Result<Hit, StepError> {
        let hit = self.next_hit(&ball.state)?;
        if self.table.wall_kind(hit.wall).is_reflecting() {
            return Ok(hit);
        }
        self.fly_open(ball, hit)
    }

    /// [`fly`](Self::fly) past a hole or periodic wall (kept out of the
    /// closed tables' hot path).
    #[cold]
    #[inline(never)]
    fn fly_open(&self, ball: &mut Ball, mut hit: Hit) -> Result<Hit, StepError> {
        let start = *ball;
        let mut time = 0.0;
        loop {
            match self.pass(ball, hit)? {
                Passage::Crossed(c) => time += c.time,
                Passage::Escaped(exit) => {
                    *ball = start;
                    return Err(StepError::Escaped(Exit {
                        time: time + exit.time,
                        ..exit
                    }));
                }
            }
            hit = self.next_hit(&ball.state)?;
            if self.table.wall_kind(hit.wall).is_reflecting() {
                hit.time += time;
                return Ok(hit);
            }
        }
    }

    /// Pass the ball through the open wall of `hit`: into the next cell
    /// (a crossing) or out of the table (an escape; the ball is left at
    /// the hole).
    fn pass(&self, ball: &mut Ball, hit: Hit) -> Result<Passage, StepError> {
        let zero_run = watch_zero_time(ball, &hit)?;
        Ok(match self.table.wall_kind(hit.wall) {
            WallKind::Periodic {
                partner,
                shift,
                step,
            } => {
                let point = hit.point - shift;
                ball.state.position = point;
                ball.cell = ball.cell.moved(step);
                ball.zero_run = zero_run;
                Passage::Crossed(Crossing {
                    time: hit.time,
                    wall: hit.wall,
                    partner,
                    point,
                    cell: ball.cell,
                })
            }
            WallKind::Hole | WallKind::Reflecting => {
                ball.state.position = hit.point;
                Passage::Escaped(Exit {
                    time: hit.time,
                    wall: hit.wall,
                    point: hit.point,
                    s: hit.s(),
                    v_par: ball.state.velocity.dot(hit.tangent()),
                    spin: ball.state.spin,
                })
            }
        })
    }

    /// Fly to the next wall and do what it does: collide, cross into the
    /// next cell, or escape ([`Event`]). On a closed table every event is
    /// a collision, as [`step`](Self::step) takes it; a hole-free table
    /// never reports an escape. After an escape the ball sits at the hole
    /// with the velocity and spin it left with; advancing it again is a
    /// caller's error (it would fly on out of the table).
    ///
    /// # Errors
    /// As [`step`](Self::step), but an escape is an [`Event::Escape`], not
    /// an error.
    #[inline]
    pub fn advance(&self, ball: &mut Ball) -> Result<Event, StepError> {
        let hit = self.next_hit(&ball.state)?;
        if !self.table.wall_kind(hit.wall).is_reflecting() {
            return Ok(match self.pass(ball, hit)? {
                Passage::Crossed(c) => Event::Crossing(c),
                Passage::Escaped(e) => Event::Escape(e),
            });
        }
        self.collide(ball, hit).map(Event::Collision)
    }

    /// The ball's unwrapped position on a periodic table: its cell's
    /// lattice offset plus its position in the cell (the cell is an exact
    /// integer count, so this is exact to the rounding of one sum). On any
    /// other table, its position.
    #[must_use]
    pub fn unwrapped(&self, ball: &Ball) -> DVec2 {
        match self.table.lattice() {
            Some(basis) => ball.cell.offset(basis) + ball.state.position,
            None => ball.state.position,
        }
    }

    /// Apply the law at `hit` and put the velocity back on the ball's shell.
    #[inline]
    fn reflect(&self, ball: &Ball, hit: &Hit) -> (DVec2, f64) {
        let s = &ball.state;
        let (v, u) = self.law.collide(s.velocity, s.spin, hit.tangent());
        // One Newton step back onto the launch shell: c = 1 + O(ε), so after
        // every collision |V|² is within an ulp or two of the shell. Errors
        // can neither drift (bias) nor random-walk (accumulate). Restoring the
        // incoming velocity instead would take the multiply-add off the
        // critical path, but leaves each collision's own rounding (up to ~10
        // ulps near grazing hits) in the state; we keep the tighter bound.
        let c = 1.5 - 0.5 * self.law.norm2(v, u) * ball.inv_shell;
        let u = if self.law.is_coupled() { u * c } else { u };
        (v * c, u)
    }

    #[inline]
    fn record(&self, hit: Hit, before: &State, v_after: DVec2, u_after: f64) -> Collision {
        let t = hit.tangent();
        let v_par_before = before.velocity.dot(t);
        Collision {
            hit,
            v_par_before,
            spin_before: before.spin,
            v_par_after: v_after.dot(t),
            spin_after: u_after,
            q: self.law.q(v_par_before, before.spin),
        }
    }

    /// Fly to the next wall and collide (one step of the collision map).
    ///
    /// # Errors
    /// [`StepError`] if no wall lies ahead, a value turns non-finite, or the
    /// ball is stuck ([`StepError::Stuck`]: more than
    /// [`MAX_ZERO_TIME_RUN`](crate::MAX_ZERO_TIME_RUN) zero-time collisions
    /// in a row); the ball is left unchanged then.
    ///
    /// On a periodic table the ball flies through periodic walls on the
    /// way (its [`cell`](Ball::cell) counted, no collision), and the
    /// collision's flight time is the whole flight since the last
    /// collision; on a table with holes, reaching a hole is
    /// [`StepError::Escaped`] (the ball left as it was). [`advance`](Self::advance)
    /// reports crossings and escapes as events instead.
    #[inline]
    pub fn step(&self, ball: &mut Ball) -> Result<Collision, StepError> {
        let hit = self.fly(ball)?;
        self.collide(ball, hit)
    }

    /// Collide at the reflecting wall of `hit`.
    #[inline]
    fn collide(&self, ball: &mut Ball, hit: Hit) -> Result<Collision, StepError> {
        let zero_run = watch_zero_time(ball, &hit)?;
        let (v, u) = self.reflect(ball, &hit);
        let before = ball.state;
        ball.state = State::new(hit.point, v, u);
        ball.zero_run = zero_run;
        Ok(self.record(hit, &before, v, u))
    }

    /// Take `collisions` steps, showing each to `observer`.
    ///
    /// # Errors
    /// The first [`StepError`]; the ball stays where that step started.
    pub fn run<O: Observer + ?Sized>(
        &self,
        ball: &mut Ball,
        collisions: u64,
        observer: &mut O,
    ) -> Result<Run, StepError> {
        let mut run = Run::default();
        for _ in 0..collisions {
            let c = self.step(ball)?;
            run.collisions += 1;
            run.time += c.time();
            observer.observe(&c, &ball.state);
        }
        Ok(run)
    }

    /// One step that also carries tangent vectors with the exact linearised
    /// flow ([`docs/PHYSICS.md`](https://github.com/spinball/spinball/blob/main/docs/PHYSICS.md#exact-tangent-dynamics),
    /// "Exact tangent dynamics"): free flight `δx += τ δv`,
    /// then the collision rule with its curvature term. The vectors are
    /// tangent vectors of the *flow*: after the step they describe a neighbour
    /// at the time of the reference collision.
    ///
    /// # Errors
    /// As [`step`](Self::step).
    #[inline]
    pub fn step_tangent(
        &self,
        ball: &mut Ball,
        tangents: &mut [TangentVector],
    ) -> Result<Collision, StepError> {
        // A crossing translates the ball and leaves tangent vectors as they
        // are, so the flight through periodic walls is one free flight.
        let hit = self.fly(ball)?;
        let zero_run = watch_zero_time(ball, &hit)?;
        let (v, u) = self.reflect(ball, &hit);
        let before = ball.state;
        let frame = TangentFrame::new(&self.law, &hit, &before, v);
        for tv in tangents.iter_mut() {
            tv.dx += tv.dv * hit.time;
            frame.apply(tv);
        }
        ball.state = State::new(hit.point, v, u);
        ball.zero_run = zero_run;
        Ok(self.record(hit, &before, v, u))
    }

    /// One step and the 5×5 Jacobian of the flight–collision step in the
    /// coordinates `(x, y, v_x, v_y, u)` (flow version: the neighbour is
    /// compared at the reference's collision time). Its determinant is −1 for
    /// α > 0 and +1 at α = 0.
    ///
    /// # Errors
    /// As [`step`](Self::step).
    pub fn step_jacobian(&self, ball: &mut Ball) -> Result<(Collision, Jacobian), StepError> {
        let mut basis: [TangentVector; 5] =
            std::array::from_fn(|i| TangentVector::from_array(unit(i)));
        let c = self.step_tangent(ball, &mut basis)?;
        let mut j = [[0.0; 5]; 5];
        for (col, tv) in basis.iter().enumerate() {
            for (row, x) in tv.to_array().into_iter().enumerate() {
                j[row][col] = x;
            }
        }
        Ok((c, Jacobian(j)))
    }
}

/// A pass through an open wall: into the next cell, or out of the table.
enum Passage {
    Crossed(Crossing),
    Escaped(Exit),
}

fn unit(i: usize) -> [f64; 5] {
    let mut e = [0.0; 5];
    e[i] = 1.0;
    e
}
