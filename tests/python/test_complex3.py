"""grassfire.medial3d and grassfire.burn3d against the program's --json and --ply outputs."""
import json
import math
import os
import tempfile
import unittest

import numpy as np

import grassfire
from support import PROJECT_DATA, TEST_DATA, cli_error, cli_json, run_cli, same_number

TIMING_KEYS = ("seconds", "total_seconds")


def without_timings(value):
    """The report without its wall-clock members (they differ between two runs), and
    without the exact engine's kinks, merges, quenches and tangents (the module turns those lists of
    records into columns; kink_times compares the kinks)."""
    if isinstance(value, dict):
        return {k: without_timings(v) for k, v in value.items()
                if not any(t in k for t in TIMING_KEYS) and k not in ("kinks", "merges", "quenches", "tangents")}
    return value


def kink_times(stats):
    """BT at the kinks, from the program's list of records or the module's columns."""
    k = stats.get("kinks", [])
    if isinstance(k, dict):
        return [float(v) for v in k.get("bt", [])]
    return [float(x["bt"]) for x in k]


def read_ply(path):
    """Vertex rows (x, y, z, scalars...), their column names, triangles and segments of the
    program's ASCII PLY (kernel/io/complex_export.cpp)."""
    with open(path, encoding="utf-8") as f:
        lines = f.read().splitlines()
    end = lines.index("end_header")
    counts, columns, element = {}, [], None
    for line in lines[:end]:
        words = line.split()
        if words[0] == "element":
            element = words[1]
            counts[element] = int(words[2])
        elif words[0] == "property" and element == "vertex":
            columns.append(words[-1])
    nv, nf, ne = counts["vertex"], counts["face"], counts["edge"]
    body = lines[end + 1:]
    rows = np.array([[float(x) for x in l.split()] for l in body[:nv]])
    faces = [[int(x) for x in l.split()[1:]] for l in body[nv:nv + nf]]
    edges = [[int(x) for x in l.split()] for l in body[nv + nf:nv + nf + ne]]
    return rows, columns, faces, edges


class Medial3dEqualsProgram(unittest.TestCase):
    def check(self, path):
        with tempfile.TemporaryDirectory(prefix=f"grassfire_py_{os.getpid()}_") as tmp:
            ply, js = os.path.join(tmp, "axis.ply"), os.path.join(tmp, "axis.json")
            code, _, err = run_cli("medial3d", path, "--ply", ply, "--json", js, "--quiet")
            self.assertEqual(code, 0, err)
            rows, columns, faces, edges = read_ply(ply)
            with open(js, encoding="utf-8") as f:
                report = json.load(f)
        r = grassfire.medial3d(path)
        np.testing.assert_array_equal(r["vertices"], rows[:, 0:3])
        np.testing.assert_array_equal(r["R"], rows[:, columns.index("R")])
        np.testing.assert_array_equal(r["triangles"], np.array(faces, dtype=np.int64).reshape(-1, 3))
        np.testing.assert_array_equal(r["segments"], np.array(edges, dtype=np.int64).reshape(-1, 2))
        self.assertEqual(r["vertices"].shape, (report["axis"]["vertices"], 3))
        self.assertEqual(r["triangles"].shape, (report["axis"]["triangles"], 3))
        arrays = ("vertices", "triangles", "segments", "R")
        got = without_timings({k: v for k, v in r.items() if k not in arrays})
        self.assert_same_report(got, without_timings(report))
        return r

    def assert_same_report(self, got, expected):
        """The report members, numbers lists as numpy arrays (python_values.h rules)."""
        if isinstance(expected, dict):
            self.assertEqual(set(got), set(expected))
            for k in expected:
                self.assert_same_report(got[k], expected[k])
        elif isinstance(expected, list) and isinstance(got, np.ndarray):
            np.testing.assert_array_equal(got, np.array(expected, dtype=got.dtype))
        elif isinstance(expected, list):
            self.assertEqual(len(got), len(expected))
            for g, e in zip(got, expected):
                self.assert_same_report(g, e)
        else:
            self.assertEqual(got, expected)

    def test_convex_mesh_balls_and_halfspaces(self):
        cube = self.check(os.path.join(PROJECT_DATA, "meshes", "cube.off"))
        self.assertGreater(len(cube["triangles"]), 0)
        self.check(os.path.join(TEST_DATA, "builders3", "cube.hs"))
        self.check(os.path.join(TEST_DATA, "3d", "tetrahedron.off"))

    def test_errors_have_the_programs_messages(self):
        for path in ("bad_nan.off", "bad_index.off", "bad_nan.cin"):
            full = os.path.join(TEST_DATA, "3d", path)
            with self.subTest(path=path):
                expected = cli_error("medial3d", full)
                with self.assertRaises((ValueError, RuntimeError)) as caught:
                    grassfire.medial3d(full)
                self.assertEqual(str(caught.exception), expected)
        with self.assertRaisesRegex(ValueError, "samples must be in"):
            grassfire.medial3d(os.path.join(PROJECT_DATA, "meshes", "cube.off"), samples=0)


class Burn3dEqualsProgram(unittest.TestCase):
    def check(self, source, spacing, *extra):
        doc = cli_json("burn3d", source, "--spacing", str(spacing), *extra)
        method = extra[extra.index("--method") + 1] if "--method" in extra else "discrete"
        r = grassfire.burn3d(source, spacing=spacing, mesh_is_complex="--mesh-is-complex" in extra, method=method)
        values = doc["vertex_values"]
        np.testing.assert_array_equal(r["vertices"], np.column_stack([values["x"], values["y"], values["z"]]))
        np.testing.assert_array_equal(r["R"], values["R"])
        for field in ("BT", "ET"):
            self.assertIsInstance(r[field], np.ndarray)
            expected = [math.inf if v is None else v for v in values[field]]
            self.assertEqual(len(r[field]), len(expected))
            for got, want in zip(r[field], expected):
                self.assertTrue(same_number(got, want), (field, got, want))
        for key in ("input", "method", "complex", "summary", "sources", "queries"):
            self.assertEqual(r[key], doc[key], key)
        self.assertEqual(r.get("spacing"), doc.get("spacing"))  # the discrete method's only
        self.assertEqual(without_timings(r["stats"]), without_timings(doc["stats"]))
        self.assertEqual(kink_times(r["stats"]), kink_times(doc["stats"]))
        self.assertEqual(r["triangles"].shape, (doc["complex"]["triangles"], 3))
        self.assertNotIn("vertex_values", r)
        return r

    def test_synthetic_ma_and_mesh(self):
        fin = self.check("board-fin", 0.25)
        self.assertTrue(np.all(np.isfinite(fin["BT"][np.isfinite(fin["ET"])])))
        self.check("book:3", 0.25)
        self.check(os.path.join(PROJECT_DATA, "ma", "box_4_3_1.ma"), 0.2)
        self.check(os.path.join(PROJECT_DATA, "meshes", "cube.off"), 0.1, "--mesh-is-complex")
        # The exact method through the same table: a closed surface without sources never burns.
        exact = self.check(os.path.join(PROJECT_DATA, "meshes", "cube.off"), 0.1, "--mesh-is-complex", "--method", "exact")
        self.assertTrue(np.all(np.isinf(exact["BT"])))
        self.assertEqual(len(exact["BT_error"]), len(exact["BT"]))
        self.assertEqual(exact["stats"]["uncertified"], 0)

    def test_tetrahedron_surface_never_burns(self):
        # A closed surface has no border: nothing ignites, BT is infinite everywhere (Prop 7).
        r = grassfire.burn3d("tetrahedron", spacing=0.5)
        self.assertTrue(np.all(np.isinf(r["BT"])))
        self.assertEqual(r["summary"]["unburned_vertices"], len(r["vertices"]))

    def test_errors(self):
        expected = cli_error("burn3d", "nope.ma")
        with self.assertRaises(RuntimeError) as caught:
            grassfire.burn3d("nope.ma")
        self.assertEqual(str(caught.exception), expected)
        # method="exact" goes through the program's method table: while the program refuses
        # it, the module raises the program's message; once it runs, the two agree.
        code, _, _ = run_cli("burn3d", "board-fin", "--method", "exact", "--quiet")
        if code != 0:
            expected = cli_error("burn3d", "board-fin", "--method", "exact")
            with self.assertRaises(RuntimeError) as caught:
                grassfire.burn3d("board-fin", method="exact")
            self.assertEqual(str(caught.exception), expected)
        else:
            self.check("board-fin", 0.25, "--method", "exact")
        with self.assertRaisesRegex(ValueError, "unknown method 'dijkstra'"):
            grassfire.burn3d("board-fin", method="dijkstra")
        with self.assertRaisesRegex(ValueError, "spacing must be a positive number"):
            grassfire.burn3d("board-fin", spacing=-1.0)


if __name__ == "__main__":
    unittest.main()
