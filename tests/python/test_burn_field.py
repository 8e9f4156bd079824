"""curves3d, paths3d and prune3d from Python with field=: the burning `burn3d --field` wrote,
read instead of burning again, gives the same results; a field of another complex is refused
naming the file."""
import os
import tempfile
import unittest

import numpy as np

import grassfire
from support import run_cli


def same_result(test, a, b, path=""):
    """Equal members but for timings ("seconds")."""
    if isinstance(a, dict):
        test.assertEqual(sorted(k for k in a if k != "seconds"), sorted(k for k in b if k != "seconds"), path)
        for k in a:
            if k != "seconds":
                same_result(test, a[k], b[k], path + "/" + k)
    elif isinstance(a, np.ndarray):
        test.assertTrue(np.array_equal(a, b, equal_nan=a.dtype.kind == "f"), path)
    elif isinstance(a, list):
        test.assertEqual(len(a), len(b), path)
        for i, (x, y) in enumerate(zip(a, b)):
            same_result(test, x, y, f"{path}[{i}]")
    else:
        test.assertEqual(a, b, path)


class FieldFile(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory(prefix=f"grassfire_py_{os.getpid()}_")
        cls.field = os.path.join(cls.tmp.name, "board_fin_field.json")
        code, _, err = run_cli("burn3d", "board-fin", "--spacing", "0.1", "--field", cls.field, "--quiet")
        assert code == 0, err

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_same_results_as_burning_again(self):
        same_result(self, grassfire.curves3d("board-fin", spacing=0.1), grassfire.curves3d("board-fin", field=self.field))
        same_result(self, grassfire.paths3d("board-fin", spacing=0.1),
                    grassfire.paths3d("board-fin", field=self.field))
        same_result(self, grassfire.prune3d("board-fin", et=0.5, method="discrete", spacing=0.1),
                    grassfire.prune3d("board-fin", et=0.5, method="discrete", field=self.field))

    def test_another_complex_is_refused(self):
        with self.assertRaises(RuntimeError) as e:
            grassfire.curves3d("annulus", field=self.field)
        self.assertIn(self.field + ": the field was burned on another complex", str(e.exception))
        with self.assertRaises(ValueError) as e:
            grassfire.curves3d("board-fin", field=self.field, spacing=0.2)
        self.assertIn("is not the spacing of --field " + self.field, str(e.exception))
        with self.assertRaises(ValueError):
            grassfire.curves3d("board-fin", field=3)


if __name__ == "__main__":
    unittest.main()
