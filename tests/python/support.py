"""Helpers for the Python tests: the program under test, temporary folders, comparisons.

The tests compare what the module returns with what the program (`grassfire`, GF_CLI)
writes for the same input: the same kernel code through two interfaces.
"""
import json
import os
import struct
import subprocess
import tempfile
import zlib

import numpy as np

CLI = os.environ["GF_CLI"]
TEST_DATA = os.environ["GF_TEST_DATA"]
PROJECT_DATA = os.environ["GF_PROJECT_DATA"]


def run_cli(*args):
    """Runs `grassfire ARGS`; returns (exit code, stdout, stderr)."""
    p = subprocess.run([CLI, *args], capture_output=True, text=True, check=False)
    return p.returncode, p.stdout, p.stderr


def cli_error(command, *args):
    """The message the program prints for a failing command, without its 'grassfire CMD: ' prefix."""
    code, _, err = run_cli(command, *args)
    assert code == 1, f"grassfire {command} {args} exited {code}: {err}"
    prefix = f"grassfire {command}: "
    line = err.strip().splitlines()[-1]
    assert line.startswith(prefix), line
    return line[len(prefix):]


def cli_json(command, *args):
    """Runs a command with --json into a temporary file and returns the parsed document."""
    with tempfile.TemporaryDirectory(prefix=f"grassfire_py_{os.getpid()}_") as tmp:
        out = os.path.join(tmp, "out.json")
        code, _, err = run_cli(command, *args, "--json", out, "--quiet")
        assert code == 0, err
        with open(out, encoding="utf-8") as f:
            return json.load(f)


def json_number(x):
    """A number of the JSON as the module gives it: 'inf' -> inf, null -> nan."""
    if x is None:
        return float("nan")
    if isinstance(x, str):
        return {"inf": float("inf"), "-inf": float("-inf")}[x]
    return x


def same_number(a, b):
    """Equal as doubles, nan equal to nan (no tolerance: both come from the same values)."""
    a, b = float(a), float(b)
    return a == b or (a != a and b != b)


def write_png_gray(path, rows):
    """A minimal 8-bit grayscale PNG (rows: lists of 0..255), written without the kernel."""
    height, width = len(rows), len(rows[0])
    raw = b"".join(b"\x00" + bytes(r) for r in rows)

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)

    header = struct.pack(">IIBBBBB", width, height, 8, 0, 0, 0, 0)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


def is_array(x):
    return isinstance(x, np.ndarray)
