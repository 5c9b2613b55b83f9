"""Films from Python: ``spinball.animate`` writes a GIF with the frames,
size and delay asked for, returns the frames it drew, refuses bad input,
and writes the same bytes as the command line's ``spinball animate``
(found through SPINBALL, as in test_rust_sweep.py)."""

import os
import shutil
import struct
import subprocess

import numpy as np
import pytest

import spinball as sb


def gif_frames(path):
    """Screen size and the delay of every frame of a GIF, by walking its
    blocks (GIF89a: header, global colour table, extensions, images)."""
    data = open(path, "rb").read()
    assert data[:6] == b"GIF89a"
    width, height, packed = struct.unpack("<HHB", data[6:11])
    at = 13 + (3 * 2 ** ((packed & 7) + 1) if packed & 0x80 else 0)
    delays, delay = [], None

    def skip_sub_blocks(i):
        while data[i]:
            i += data[i] + 1
        return i + 1

    while data[at] != 0x3B:
        if data[at] == 0x21:
            if data[at + 1] == 0xF9:
                delay = struct.unpack("<H", data[at + 4 : at + 6])[0]
            at = skip_sub_blocks(at + 2)
        elif data[at] == 0x2C:
            packed = data[at + 9]
            at += 10 + (3 * 2 ** ((packed & 7) + 1) if packed & 0x80 else 0)
            at = skip_sub_blocks(at + 1)
            delays.append(delay)
        else:
            raise AssertionError(f"unexpected block 0x{data[at]:02x} at {at}")
    return (width, height), delays


def test_a_gif_with_the_frames_asked_for_and_its_frames_returned(tmp_path):
    path = tmp_path / "sub" / "stadium.gif"
    film = sb.animate(
        sb.Stadium(a=1), 0.5, path, balls=3, seed=2, fps=10, duration=1.5, size=(200, 150)
    )
    size, delays = gif_frames(path)
    assert size == (200, 150)
    assert delays == [10] * 15
    assert film["positions"].shape == (3, 15, 2)
    assert film["angles"].shape == film["spins"].shape == (3, 15)
    assert np.allclose(film["times"], np.arange(15) * film["speed"] / 10)
    assert film["speed"] == 4.0 and film["radius"] == 0.1
    # Inside the stadium (caps of radius 1 about x = ±1), to rounding.
    x, y = film["positions"][..., 0], film["positions"][..., 1]
    dist = np.hypot(np.maximum(np.abs(x) - 1.0, 0.0), y)
    assert np.all(dist <= 1.0 + 1e-12)
    # Between frames in one flight the angle turns at ω = u / r.
    step = np.diff(film["angles"], axis=1)
    same = film["spins"][:, 1:] == film["spins"][:, :-1]
    expect = film["spins"][:, 1:] * 0.4 / film["radius"]
    assert np.allclose(step[same], expect[same])
    assert np.all(film["collisions"] > 0)


def test_explicit_starts(tmp_path):
    starts = np.array([[-1.5, -1.5, 0.6, 0.8, 0.3], [1.5, 1.5, -0.8, 0.6, 0.0]])
    film = sb.animate(
        "sinai:L=2,R=1", 0.4, tmp_path / "sinai.gif", initial_states=starts, fps=8, duration=1
    )
    assert film["positions"].shape == (2, 8, 2)
    assert np.array_equal(film["positions"][:, 0], starts[:, :2])
    assert np.array_equal(film["spins"][:, 0], starts[:, 4])


def test_bad_films_are_refused(tmp_path):
    gif = tmp_path / "x.gif"
    with pytest.raises(ValueError, match=r"\.gif or \.mp4"):
        sb.animate("stadium:a=1", 0.5, tmp_path / "x.png")
    with pytest.raises(ValueError, match="at most 50 fps"):
        sb.animate("stadium:a=1", 0.5, gif, fps=60)
    with pytest.raises(ValueError, match="fps"):
        sb.animate("stadium:a=1", 0.5, gif, fps=0)
    with pytest.raises(ValueError, match="balls"):
        sb.animate("stadium:a=1", 0.5, gif, balls=0)
    with pytest.raises(ValueError, match="outside"):
        sb.animate("stadium:a=1", 0.5, gif, initial_states=[[5, 0, 1, 0, 0]])
    with pytest.raises(ValueError, match="too small"):
        sb.animate("stadium:a=1", 0.5, gif, size=(20, 20))
    assert not gif.exists()
    if shutil.which("ffmpeg") is None:
        with pytest.raises(RuntimeError, match="install ffmpeg"):
            sb.animate("stadium:a=1", 0.5, tmp_path / "x.mp4")
        print("skipped: ffmpeg is not on PATH, no MP4 was written")
    else:
        sb.animate("stadium:a=1", 0.5, tmp_path / "x.mp4", duration=0.5)
        assert (tmp_path / "x.mp4").stat().st_size > 500


def test_same_film_as_the_command_line(tmp_path):
    exe = os.environ.get("SPINBALL")
    if not exe:
        pytest.skip("SPINBALL (the spinball binary) is not set")
    common = dict(balls=2, seed=5, fps=10, duration=1.0, size=(160, 120), title="t")
    sb.animate("stadium:a=1", 0.3, tmp_path / "py.gif", **common)
    subprocess.run(
        [exe, "animate", "--table", "stadium:a=1", "--alpha", "0.3", "--balls", "2",
         "--seed", "5", "--fps", "10", "--duration", "1", "--size", "160x120",
         "--title", "t", "--quiet", "-o", str(tmp_path / "cli.gif")],
        check=True,
    )
    assert (tmp_path / "py.gif").read_bytes() == (tmp_path / "cli.gif").read_bytes()
