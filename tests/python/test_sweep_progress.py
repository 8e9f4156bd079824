"""Progress of the exact engine's sweep from Python (support/progress.h, the same lines as
`grassfire burn3d --method exact --progress`): the event time against the largest ignition
time and the estimate of the final time, the events and the windows, during the run.
GRASSFIRE_PROGRESS_SECONDS=0 shows every report instead of one a second: no timing in the test.
"""
import os
import re
import subprocess
import sys
import unittest

SWEEP = re.compile(r"^burn3d: (\d+)%, \d+ s, t = (\S+) \(largest ignition (\S+), final ~(\S+)\), "
                   r"(\d+) events, (\d+) windows -- exact propagation$")


def python_stderr(verbosity):
    code = ("import grassfire\n"
            f"grassfire.set_verbosity({verbosity!r})\n"
            "grassfire.burn3d('board-fin', method='exact')\n")
    env = dict(os.environ, GRASSFIRE_PROGRESS_SECONDS="0")
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True, env=env).stderr


class SweepProgress(unittest.TestCase):
    def test_lines_during_the_sweep(self):
        err = python_stderr("progress")
        lines = [m for m in map(SWEEP.match, err.splitlines()) if m]
        self.assertGreaterEqual(len(lines), 2, err)
        events = [int(m.group(5)) for m in lines]
        self.assertEqual(events, sorted(set(events)))
        for m in lines:
            self.assertLessEqual(int(m.group(1)), 99)
            self.assertGreaterEqual(float(m.group(4)), float(m.group(3)))
            self.assertGreater(int(m.group(6)), 0)

    def test_quiet_shows_none(self):
        self.assertEqual(python_stderr("quiet"), "")


if __name__ == "__main__":
    unittest.main()
