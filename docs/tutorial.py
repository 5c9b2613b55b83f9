# %% [markdown]
# # spinball tutorial: from a table to λ(α), a section and an FTLE map
#
# A ball that carries spin `u = rω` moves freely inside a table; at each
# wall it trades tangential velocity for spin through `α = I/(m r²)`
# (0 specular, 0.4 solid sphere, 0.5 disk, 1 thin ring). This tutorial
# walks through what the Python package shows of it: a table, a
# trajectory coloured by spin, the largest Lyapunov exponent λ(α) with its
# error bars, the distribution of finite-time exponents, a Birkhoff section
# and an FTLE map of the section.
#
# It is a Python script in "percent" format: run it as a script
# (`python docs/tutorial.py`, headless with `MPLBACKEND=Agg`), or open it as
# a notebook in Jupyter (with jupytext) or VS Code, cell by cell. It needs
# the package with its plotting extra, from a clone:
#
# ```sh
# pip install './crates/spinball-py[plot]'
# ```
#
# The figures go to a fresh temporary directory (or to
# `$SPINBALL_TUTORIAL_OUT` if set). The whole script runs in well under a
# minute; the sizes are small on purpose, and each cell says what to raise
# for a figure worth publishing.

# %%
import os
import tempfile
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

import spinball
from spinball import plot

out = Path(os.environ.get("SPINBALL_TUTORIAL_OUT") or tempfile.mkdtemp(prefix="spinball-tutorial-"))
out.mkdir(parents=True, exist_ok=True)
print("figures go to", out)


def save(ax, name):
    """Save the figure of `ax` as `name` in the output directory."""
    path = out / name
    ax.figure.savefig(path, dpi=100, bbox_inches="tight")
    plt.close(ax.figure)
    print("wrote", path)


# %% [markdown]
# ## A table
#
# The Bunimovich stadium: two half-disks of radius 1 joined by flats of
# length `2a`. Tables are built in Rust and validated there; a spec string
# such as `"stadium:a=1"` works wherever a table does. `plot.table` draws
# the outline the library computes (`Table.outline()`).

# %%
stadium = spinball.Stadium(a=1.0)
print(stadium, "area", stadium.area, "perimeter", stadium.perimeter)
save(plot.table(stadium), "table.png")

# %% [markdown]
# ## One trajectory, coloured by spin
#
# At α = 0.5 every collision changes the spin; each flight is coloured by
# the spin it carries. The black dot is the start.

# %%
billiard = spinball.Billiard(stadium, 0.5)
traj = billiard.trajectory(60, position=(0.3, 0.2), velocity=(0.6, 0.8), spin=0.0)
print(len(traj), "collisions; spin after the last:", traj.u[-1])
save(plot.trajectory(stadium, traj), "trajectory.png")

# %% [markdown]
# ## λ(α) with error bars
#
# `alpha_sweep` runs one ensemble of starts per α and returns a
# `LyapunovResult` for each: the mean exponent with its standard error
# (SEM), the median, the chaotic fraction, the cost and every parameter.
# `plot.lyapunov` draws the means with their SEM as error bars over the
# markers (the legend gives the largest SEM: with many starts the bars are
# shorter than the markers). For the paper's precision use `ics=1000` and
# `collisions=10_000` or more.

# %%
alphas = [0.0, 0.25, 0.5, 0.75, 1.0]
results = spinball.alpha_sweep(stadium, alphas, ics=64, collisions=2000, seed=1)
for r in results:
    print(f"α = {r.alpha:4}: λ = {spinball.plus_minus(r.mean, r.sem)}, chaotic fraction {r.chaotic_fraction:.2f}")
save(plot.lyapunov(results), "lambda_alpha.png")

# %% [markdown]
# ## The distribution behind one λ
#
# Each start has its own finite-time exponent; starts trapped near a
# regular island have exponents near 0. The chaos threshold (0.01) splits
# them, and the chaotic fraction is quoted over a band of thresholds
# (`spinball.THRESHOLD_BAND`).

# %%
r = results[2]
ftle = r.ftle()
fig, ax = plt.subplots()
ax.hist(ftle.exponents, bins=30, color="#0072b2", alpha=0.6, label="starts")
band = spinball.THRESHOLD_BAND
ax.axvspan(min(band), max(band), color="#e69f00", alpha=0.25, label="chaos thresholds")
ax.axvline(ftle.mean, color="black", label=f"mean {spinball.plus_minus(r.mean, r.sem)}")
ax.set_xlabel("finite-time exponent λ (1/time)")
ax.set_ylabel("count")
ax.set_title(f"{r.table} at α = {r.alpha}")
ax.legend()
save(ax, "ftle_histogram.png")

# %% [markdown]
# ## A Birkhoff section
#
# Every collision of a few orbits as a point `(s, sin θ)`: `s` the arc
# length along the wall, `θ` the angle to the normal. Regular orbits trace
# curves, chaotic ones fill regions. Colour: the spin at the collision.

# %%
sec = spinball.section(stadium, 0.5, orbits=8, collisions=1000, seed=1)
save(plot.section(sec, table=stadium), "section.png")

# %% [markdown]
# ## An FTLE map of the section
#
# The finite-time exponent of a grid of starts at fixed spin `u = 0`: the
# dark region is regular. On a stadium the library predicts where the
# bouncing-ball island is (a pair of flat-wall collisions rotates
# `(v∥, √α u)` by `4·arctan √α`), outlined in red. Raise `columns`, `rows`
# and `collisions` for a sharper map.

# %%
m = spinball.ftle_map(stadium, 0.5, columns=48, rows=32, collisions=300, seed=1)
print(f"{m['regular']} of {m['on_shell']} cells regular; chaotic fraction {m['chaotic_fraction']:.3f}")
save(plot.ftle_map(m), "ftle_map.png")

# %% [markdown]
# ## Composing pictures
#
# Every `plot` function draws into the axes it is given and returns them,
# so panels combine: λ(α) of two tables on one axes, or a table beside its
# map.

# %%
fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4))
plot.table("sinai:L=2,R=1", ax=left)
sinai = spinball.alpha_sweep("sinai:L=2,R=1", alphas, ics=32, collisions=1000, seed=1)
plot.lyapunov(results, ax=right, label="stadium a = 1")
plot.lyapunov(sinai, ax=right, label="Sinai L = 2, R = 1")
right.legend(fontsize="small")
save(right, "composed.png")

# %% [markdown]
# ## An animation
#
# A film of three balls in the stadium, without spin and with α = 0.5: the
# white marker on each ball turns with its spin. The library draws it (GIF
# here; `.mp4` where ffmpeg is installed).

# %%
for a in (0.0, 0.5):
    film = plot.animate(stadium, a, out / f"stadium-alpha{a}.gif", balls=3, fps=10, duration=3.0, size=(320, 200))
    print(f"α = {a}: {film['positions'].shape[1]} frames, {int(film['collisions'].sum())} collisions")

# %%
print("done: the figures are in", out)
