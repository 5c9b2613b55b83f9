"""Python vs Rust: the same λ ensemble, timed both ways.

The ensemble of docs/PERFORMANCE.md: stadium a = 1, α = 0.5, the paper's
sampler, finite differences (δ0 = 1e-7), 4000 initial conditions × 20 000
collisions, seed 1. The Rust side is `spinball sweep` (its JSON
`wall_time_s`, and the whole process as seen from outside); the Python side
is `spinball.lyapunov` (its `wall_time_s`, and the call as seen from
Python, argument parsing and result conversion included). Runs alternate,
so a change of machine load hits both; the medians are printed with the
ratio and a check that both computed the same numbers.

    python crates/spinball-py/bench/bench_lyapunov.py --spinball target/release/spinball

Options: --runs N (5), --ics, --collisions, --threads (all cores).
"""

import argparse
import json
import os
import statistics
import subprocess
import tempfile
import time

import spinball as sb


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--spinball", default=os.environ.get("SPINBALL", "target/release/spinball"))
    p.add_argument("--runs", type=int, default=5)
    p.add_argument("--ics", type=int, default=4000)
    p.add_argument("--collisions", type=int, default=20_000)
    p.add_argument("--threads", type=int, default=None)
    a = p.parse_args()
    common = ["--table", "stadium:a=1", "--alphas", "0.5", "--ics", str(a.ics),
              "--collisions", str(a.collisions), "--method", "fd", "--seed", "1"]
    if a.threads:
        common += ["--threads", str(a.threads)]
    rust_in, rust_out, py_in, py_out = [], [], [], []
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "sweep.json")
        for k in range(a.runs):
            t0 = time.perf_counter()
            subprocess.run([a.spinball, "sweep", *common, "--json", path], check=True, stdout=subprocess.DEVNULL)
            rust_out.append(time.perf_counter() - t0)
            point = json.load(open(path))["points"][0]
            rust_in.append(point["wall_time_s"])
            t0 = time.perf_counter()
            r = sb.lyapunov("stadium:a=1", 0.5, ics=a.ics, collisions=a.collisions, method="fd",
                            seed=1, threads=a.threads)
            py_out.append(time.perf_counter() - t0)
            py_in.append(r.wall_time_s)
            assert (r.mean, r.sem) == (point["mean"], point["sem"]), "different numbers"
            print(f"run {k + 1}: rust {rust_in[-1]:.3f} s (process {rust_out[-1]:.3f} s), "
                  f"python {py_in[-1]:.3f} s (call {py_out[-1]:.3f} s)")
    steps = a.ics * a.collisions
    med = statistics.median
    print(f"\n{a.ics} ICs x {a.collisions} collisions, median of {a.runs} runs:")
    print(f"  rust   sweep wall_time_s {med(rust_in):.3f} s = {med(rust_in) / steps * 1e9:.2f} ns/IC-step")
    print(f"  python lyapunov call     {med(py_out):.3f} s = {med(py_out) / steps * 1e9:.2f} ns/IC-step"
          f" (its wall_time_s {med(py_in):.3f} s)")
    print(f"  ratio python call / rust: {med(py_out) / med(rust_in):.3f}"
          f" (python wall_time_s / rust: {med(py_in) / med(rust_in):.3f})")


if __name__ == "__main__":
    main()
