"""Repair from Python: every 3D function's repair, repair_alpha, repair_offset against the
program's --repair, --repair-alpha, --repair-offset on the same defective meshes (a cube
with a missing triangle: filled; two overlapping cubes: alpha-wrapped), member by member,
and the program's errors for bad repair arguments.
"""
import json
import os
import tempfile
import unittest

import numpy as np

import grassfire
from support import PROJECT_DATA, cli_error, cli_json
from test_twins import plain, read_off

CUBE_V, CUBE_F = read_off(os.path.join(PROJECT_DATA, "meshes", "cube.off"))
OPEN = (CUBE_V, CUBE_F[1:])                                            # one hole: "fill"
TWO = (np.vstack([CUBE_V, CUBE_V * 0.9 + [0.5, 0.3, 0.2]]), np.vstack([CUBE_F, CUBE_F + 8]))  # "alpha_wrap"
WRAP = {"repair_alpha": 0.5, "repair_offset": 0.1}
WRAP_CLI = ("--repair-alpha", "0.5", "--repair-offset", "0.1")


def write_off(path, mesh):
    vertices, faces = mesh
    with open(path, "w", encoding="utf-8") as f:
        f.write(f"OFF\n{len(vertices)} {len(faces)} 0\n")
        for v in vertices:
            f.write(" ".join(repr(float(x)) for x in v) + "\n")
        for t in faces:
            f.write("3 " + " ".join(str(int(i)) for i in t) + "\n")


def without_times(x):
    """x without the members that are timings (they differ between two runs)."""
    if isinstance(x, dict):
        return {k: without_times(v) for k, v in x.items() if "seconds" not in k}
    if isinstance(x, list):
        return [without_times(v) for v in x]
    return x


class RepairLikeTheProgram(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory(prefix="grassfire_py_repair_")
        cls.open_off = os.path.join(cls.tmp.name, "open_cube.off")
        cls.two_off = os.path.join(cls.tmp.name, "two_cubes.off")
        write_off(cls.open_off, OPEN)
        write_off(cls.two_off, TWO)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_without_repair_the_refusal_is_the_programs(self):
        expected = cli_error("medial3d", self.open_off)
        self.assertIn("--repair", expected)
        for f in (grassfire.medial3d, grassfire.complex, grassfire.burn3d, grassfire.curves3d, grassfire.prune3d):
            with self.subTest(f=f.__name__):
                with self.assertRaises(ValueError) as e:
                    f(self.open_off, **({"et": 0.1} if f is grassfire.prune3d else {}))
                self.assertEqual(str(e.exception), expected)
        with self.assertRaises(ValueError) as e:
            grassfire.medial3d(OPEN, name="open")
        self.assertEqual(str(e.exception), expected.replace(self.open_off, "open"))

    def test_medial3d_fill_and_wrap_equal_the_program(self):
        for mesh, path, kwargs, cli_args, method in ((OPEN, self.open_off, {}, (), "fill"),
                                                      (TWO, self.two_off, WRAP, WRAP_CLI, "alpha_wrap")):
            with self.subTest(method=method):
                doc = cli_json("medial3d", path, "--repair", *cli_args)
                for given in (path, mesh):
                    r = grassfire.medial3d(given, repair=True, **kwargs)
                    self.assertEqual(r["repair"]["method"], method)
                    expected = without_times(doc["repair"])
                    if given is mesh:  # the report names the array, as its messages do
                        expected = json.loads(json.dumps(expected).replace(path, "array"))
                    self.assertEqual(without_times(plain(r["repair"])), expected)
                    self.assertEqual(plain(r["axis"]), doc["axis"])
                    self.assertEqual(len(r["vertices"]), doc["axis"]["vertices"])
                if method == "alpha_wrap":
                    self.assertEqual(doc["repair"]["alpha"], 0.5)
                    self.assertEqual(doc["repair"]["offset"], 0.1)

    def test_every_3d_function_repairs(self):
        c = grassfire.complex(OPEN, repair=True)
        axis = cli_json("medial3d", self.open_off, "--repair")["axis"]
        self.assertEqual((c["counts"]["vertices"], c["counts"]["triangles"]), (axis["vertices"], axis["triangles"]))
        self.assertEqual(c["betti"].tolist(), axis["betti"])
        b = grassfire.burn3d(self.open_off, repair=True, spacing=0.25)
        bdoc = cli_json("burn3d", self.open_off, "--repair", "--spacing", "0.25")
        self.assertEqual(plain(b["summary"]), bdoc["summary"])
        self.assertEqual(b["BT"].tolist(), [v if v is not None else float("inf") for v in bdoc["vertex_values"]["BT"]])
        p = grassfire.prune3d(TWO, et=0.1, relative=True, repair=True, method="discrete", spacing=0.1, **WRAP)
        pdoc = cli_json("prune3d", self.two_off, "--et", "0.1", "--relative", "--repair", "--method", "discrete",
                        "--spacing", "0.1", *WRAP_CLI)
        for key in ("axis", "refined", "removed", "pruned", "thresholds"):
            self.assertEqual(plain(p[key]), pdoc[key], key)
        cu = grassfire.curves3d(self.open_off, repair=True, spacing=0.25)
        cdoc = cli_json("curves3d", self.open_off, "--repair", "--spacing", "0.25")
        self.assertEqual(plain(cu["betti"]), cdoc["betti"])
        self.assertEqual(len(cu["points"]), len(cdoc["nodes"]))
        pa = grassfire.paths3d(self.open_off, repair=True, spacing=0.25)
        padoc = cli_json("paths3d", self.open_off, "--repair", "--spacing", "0.25")
        self.assertEqual(plain(pa["paths"]["bt"]), [x["bt"] for x in padoc["paths"]])

    def test_bad_repair_arguments_are_the_programs_errors(self):
        cases = [({"repair_alpha": 0.5}, ("--repair-alpha", "0.5")),
                 ({"repair_offset": 0.1}, ("--repair-offset", "0.1")),
                 ({"repair": True, "repair_alpha": -1.0}, ("--repair", "--repair-alpha", "-1")),
                 ({"repair": True, "repair_offset": 0.0}, ("--repair", "--repair-offset", "0")),
                 ({"repair": True, "repair_alpha": float("inf")}, None)]
        functions = {"medial3d": grassfire.medial3d, "complex": grassfire.complex, "burn3d": grassfire.burn3d,
                     "curves3d": grassfire.curves3d, "paths3d": grassfire.paths3d, "prune3d": grassfire.prune3d}
        for kwargs, cli_args in cases:
            expected = cli_error("medial3d", self.open_off, *cli_args) if cli_args else "--repair-alpha must be a positive number"
            for name, f in functions.items():
                extra = {"et": 0.1} if name == "prune3d" else {}
                with self.subTest(f=name, kwargs=kwargs):
                    with self.assertRaises(ValueError) as e:
                        f(self.open_off, **kwargs, **extra)
                    self.assertEqual(str(e.exception), expected)
        with self.assertRaises(RuntimeError) as e:
            grassfire.burn3d(self.open_off, mesh_is_complex=True, repair=True)
        self.assertEqual(str(e.exception), cli_error("burn3d", self.open_off, "--mesh-is-complex", "--repair"))


if __name__ == "__main__":
    unittest.main()
