#!/usr/bin/env python3
"""Side by side, in one run: the authors' Numba code against spinball's lanes.

Runs `spinning_billiards.lyapunov_ensemble` (FD Benettin) and
`lyapunov_spectrum_ensemble` of a checkout of shocklab/Spinning-billiards
under numba with `numba.set_num_threads(THREADS)`, after a warm-up call, and
spinball's `lanes_speed` example (FD, exact tangent, spectrum kernels, the
lane kernels the ensembles run) on the same scenes, one after the other, and
prints ns per IC-step (wall time / (initial conditions x collisions)) and the
ratios. Nothing of the authors' code is copied into this repository: pass
the path of your own checkout.

    python3 -m venv /tmp/sbvenv && /tmp/sbvenv/bin/pip install numba numpy
    git clone https://github.com/shocklab/Spinning-billiards /tmp/spinning-billiards
    cargo build --release -p spinball-lanes --example lanes_speed
    /tmp/sbvenv/bin/python scripts/side_by_side.py /tmp/spinning-billiards \\
        --lanes-speed target/release/examples/lanes_speed

Scenes: stadium a = 1 (their STADIUM, L = 1) and Sinai L = 2, R = 1 (their
SINAI, box [-2, 2]^2, R = 1), alpha = 0.5, both on THREADS threads.
"""

import argparse
import re
import subprocess
import sys
import time

SCENES = [
    # (name, spinball table spec, authors' geometry name, p1, p2)
    ("stadium a=1", "stadium:a=1", "STADIUM", 1.0, 0.0),
    ("Sinai L=2 R=1", "sinai:L=2,R=1", "SINAI", 2.0, 1.0),
]


def authors_ns(fn, collisions, ics, alpha, geo, p1, p2, repeat):
    """Median wall ns per IC-step of one of the authors' ensembles."""
    fn(collisions // 100, 4, alpha, geo, p1, p2)  # warm-up: compile
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn(collisions, ics, alpha, geo, p1, p2)
        times.append(time.perf_counter() - t0)
    times.sort()
    return times[len(times) // 2] / (collisions * ics) * 1e9


def spinball_ns(binary, table, kernel, collisions, ics, alpha, threads, repeat,
                qr_interval=1):
    """Median wall ns per IC-step of a spinball lane kernel (best ISA)."""
    out = subprocess.run(
        [binary, "--table", table, "--kernel", kernel, "--ics", str(ics),
         "--collisions", str(collisions), "--alpha", str(alpha),
         "--threads", str(threads), "--repeat", str(repeat), "--isa", "avx512",
         "--qr-interval", str(qr_interval)],
        check=True, capture_output=True, text=True).stdout
    m = re.search(rf"^\S+\s+{kernel}\s+wall\s+([0-9.]+) ns/IC-step", out, re.M)
    if not m:
        sys.exit(f"cannot read lanes_speed output:\n{out}")
    return float(m.group(1))


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("checkout", help="path of a shocklab/Spinning-billiards checkout")
    p.add_argument("--lanes-speed", required=True, help="lanes_speed binary")
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--alpha", type=float, default=0.5)
    p.add_argument("--collisions", type=int, default=20000)
    p.add_argument("--authors-ics", type=int, default=2000)
    p.add_argument("--authors-spectrum-ics", type=int, default=200)
    p.add_argument("--ics", type=int, default=4000, help="spinball's ICs")
    p.add_argument("--repeat", type=int, default=3)
    p.add_argument("--qr-interval", type=int, default=None,
                   help="also time spinball's spectrum with Gram-Schmidt every "
                        "this many collisions (the authors' code and the default "
                        "do it every collision)")
    a = p.parse_args()

    sys.path.insert(0, a.checkout)
    import numba
    import spinning_billiards as sb

    numba.set_num_threads(a.threads)
    print(f"threads {a.threads}, alpha {a.alpha}, {a.collisions} collisions; "
          f"authors {a.authors_ics} ICs (spectrum {a.authors_spectrum_ics}), "
          f"spinball {a.ics} ICs; median of {a.repeat}; ns per IC-step (wall)")
    print("| scene | authors FD | spinball FD | ratio | spinball tangent | ratio "
          "| authors spectrum | spinball spectrum | ratio |"
          + (f" spectrum, QR every {a.qr_interval} | ratio |" if a.qr_interval else ""))
    print("|---|---|---|---|---|---|---|---|---|" + ("---|---|" if a.qr_interval else ""))
    for name, spec, geo, p1, p2 in SCENES:
        g = getattr(sb, geo)
        fd_a = authors_ns(sb.lyapunov_ensemble, a.collisions, a.authors_ics,
                          a.alpha, g, p1, p2, a.repeat)
        sp_a = authors_ns(sb.lyapunov_spectrum_ensemble, a.collisions,
                          a.authors_spectrum_ics, a.alpha, g, p1, p2, a.repeat)
        run = lambda k: spinball_ns(a.lanes_speed, spec, k, a.collisions, a.ics,
                                    a.alpha, a.threads, a.repeat)
        fd, tg, sp = run("fd"), run("tangent"), run("spectrum")
        row = (f"| {name} | {fd_a:.1f} | {fd:.2f} | {fd_a / fd:.1f}x | {tg:.2f} "
               f"| {fd_a / tg:.1f}x | {sp_a:.1f} | {sp:.2f} | {sp_a / sp:.1f}x |")
        if a.qr_interval:
            sq = spinball_ns(a.lanes_speed, spec, "spectrum", a.collisions, a.ics,
                             a.alpha, a.threads, a.repeat, a.qr_interval)
            row += f" {sq:.2f} | {sp_a / sq:.1f}x |"
        print(row, flush=True)


if __name__ == "__main__":
    main()
