"""Long calls from Python: the progress stages the program shows (set_verbosity against
--progress, stage by stage), nothing on stderr when quiet, and the GIL released during
every function's computation (another thread runs meanwhile).
"""
import os
import re
import subprocess
import sys
import threading
import time
import unittest

import grassfire
from support import PROJECT_DATA, run_cli

CAFFEINE = os.path.join(PROJECT_DATA, "balls", "caffeine.cin")
TRIPOD = os.path.join(PROJECT_DATA, "meshes", "tripod.off")
ELEPHANT = os.path.join(PROJECT_DATA, "shapes2d", "elephant-1.json")
STAGE = re.compile(r"^(\S+) .*-- (.+)$")

# (Python call, the program's arguments for the same run).
RUNS = [
    ("grassfire.medial3d(%r)" % TRIPOD, ["medial3d", TRIPOD]),
    ("grassfire.burn3d('board-fin', spacing=0.05)", ["burn3d", "board-fin", "--spacing", "0.05"]),
    ("grassfire.burn3d('tube', method='exact', spacing=0.5)", ["burn3d", "tube", "--method", "exact", "--spacing", "0.5"]),
    ("grassfire.curves3d('board-fin', spacing=0.2)", ["curves3d", "board-fin", "--spacing", "0.2"]),
    ("grassfire.paths3d('board-fin', spacing=0.2)", ["paths3d", "board-fin", "--spacing", "0.2"]),
    ("grassfire.prune3d('tube', et=3.5, spacing=0.5)", ["prune3d", "tube", "--et", "3.5", "--spacing", "0.5"]),
]


def python_stderr(call, verbosity):
    """stderr of a fresh interpreter that sets the verbosity and makes the call."""
    code = f"import grassfire\ngrassfire.set_verbosity({verbosity!r})\n{call}\n"
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True, env=os.environ)
    return p.stderr


def stages(stderr):
    """The (task word, stage) of the progress lines: what was shown, without counts and times;
    repeated lines of one stage count once (how many a long stage draws depends on its time)."""
    out = []
    for m in map(STAGE.match, stderr.splitlines()):
        if m and (not out or out[-1] != m.groups()):
            out.append(m.groups())
    return out


class ProgressLikeTheProgram(unittest.TestCase):
    def test_stages_are_the_programs(self):
        for call, args in RUNS:
            with self.subTest(call=call):
                code, _, err = run_cli(*args, "--progress")
                self.assertEqual(code, 0, err)
                expected = [s for s in stages(err) if s[1] != "writing"]  # Python writes no file
                self.assertTrue(expected, err)
                self.assertEqual(stages(python_stderr(call, "progress")), expected)

    def test_quiet_prints_nothing(self):
        for call, _ in RUNS:
            with self.subTest(call=call):
                self.assertEqual(python_stderr(call, "quiet"), "")

    def test_normal_prints_notes_only(self):
        err = python_stderr("grassfire.burn3d(%r, spacing=0.5)" % CAFFEINE, "normal")
        self.assertIn("medial axis by the balls builder", err)
        self.assertEqual(stages(err), [])

    def test_notes_name_an_array_input_as_given(self):
        # An array is written to a temporary file for the pipeline; notes and progress lines
        # name the array (its `name`), never that file.
        tetra = ("np.array([[0,0,0],[1,0,0],[0,1,0],[0,0,1]], float), "
                 "np.array([[0,2,1],[0,1,3],[0,3,2],[1,2,3]])")
        for call in (f"grassfire.burn3d(({tetra}), spacing=0.1)",
                     f"grassfire.burn3d(({tetra}), spacing=0.1, name='tetra')",
                     f"grassfire.curves3d(({tetra}), spacing=0.1)"):
            with self.subTest(call=call):
                err = python_stderr("import numpy as np\n" + call, "progress")
                name = "tetra" if "name='tetra'" in call else "array"
                self.assertIn(f": {name}: medial axis by the convex builder", err)
                self.assertIn(f" {name}: ", err)  # the progress task
                self.assertNotIn("grassfire_py_", err)
                self.assertNotIn(".off", err)


class ReleasesTheGil(unittest.TestCase):
    """Each call runs while a ticking thread is measured: with the GIL held through the
    computation the thread could not tick; the calls below take well over 20 ms."""

    CALLS = {
        "edf2d": lambda: grassfire.edf2d(ELEPHANT, exact=True),
        "prune2d": lambda: grassfire.prune2d(ELEPHANT, et=0.1, relative=True, samples=20000),
        "match2d": lambda: grassfire.match2d(ELEPHANT, ELEPHANT, samples=400),
        "medial3d": lambda: grassfire.medial3d(TRIPOD),
        "burn3d": lambda: grassfire.burn3d("board-fin", spacing=0.05),
        "complex": lambda: grassfire.complex(TRIPOD),
        "curves3d": lambda: grassfire.curves3d("board-fin", spacing=0.2),
        "paths3d": lambda: grassfire.paths3d("board-fin", spacing=0.2),
        "prune3d": lambda: grassfire.prune3d("box:12:8:4", et=0.2, relative=True, method="discrete", spacing=0.1),
    }

    def test_other_threads_run_during_every_long_call(self):
        grassfire.set_verbosity("quiet")
        try:
            for name, call in self.CALLS.items():
                with self.subTest(f=name):
                    ticks = []
                    done = threading.Event()

                    def tick():
                        while not done.is_set():
                            ticks.append(1)
                            done.wait(0.001)

                    t = threading.Thread(target=tick)
                    t.start()
                    start = time.monotonic()
                    try:
                        call()
                    finally:
                        done.set()
                        t.join()
                    seconds = time.monotonic() - start
                    self.assertGreater(seconds, 0.02, "the call is too short to measure")
                    self.assertGreater(len(ticks), 5, (seconds, len(ticks)))
        finally:
            grassfire.set_verbosity("auto")


if __name__ == "__main__":
    unittest.main()
