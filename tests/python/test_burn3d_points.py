"""grassfire.burn3d with point sources and query points against `grassfire burn3d --sources --at --csv`.

The complex is tests/data/3d/hinge.json (two triangles on a hinge edge, a segment, border
edges with linear, point and never rules). Every coordinate below is a dyadic rational, so
a float array and the CSV text denote the same exact points.
"""
import json
import math
import os
import tempfile
import unittest

import numpy as np

import grassfire
from support import TEST_DATA, cli_error, run_cli, same_number

HINGE = os.path.join(TEST_DATA, "3d", "hinge.json")
SOURCES = [[1, 0.5, 0, 0.125], [2, 0, 0, 0.25]]         # inside triangle 0; vertex 1
QUERIES = [[1, 0.5, 0], [1, 1, 0.5], [2, 0, 0], [2.5, 0, 0], [3.5, 0.25, 0], [0.5, -0.25, 0.125], [0, 0, 0]]


def write_csv(path, header, rows):
    with open(path, "w", encoding="utf-8") as f:
        f.write(header + "\n" + "".join(",".join(repr(float(x)) for x in row) + "\n" for row in rows))


def read_csv(path):
    with open(path, encoding="utf-8") as f:
        lines = f.read().splitlines()
    return lines[0].split(","), [line.split(",") for line in lines[1:]]


class Burn3dPointsEqualProgram(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory(prefix=f"grassfire_py_{os.getpid()}_")
        self.sources = os.path.join(self.tmp.name, "sources.csv")
        self.at = os.path.join(self.tmp.name, "at.csv")
        write_csv(self.sources, "x,y,z,t0", SOURCES)
        write_csv(self.at, "x,y,z", QUERIES)

    def tearDown(self):
        self.tmp.cleanup()

    def program(self, *extra):
        """The program's --csv rows and --json report for the hinge with the test's points."""
        out, js = os.path.join(self.tmp.name, "bt.csv"), os.path.join(self.tmp.name, "bt.json")
        code, _, err = run_cli("burn3d", HINGE, "--spacing", "0.125", "--at", self.at, "--csv", out, "--json", js,
                               "--quiet", *extra)
        self.assertEqual(code, 0, err)
        header, rows = read_csv(out)
        self.assertEqual(header, ["x", "y", "z", "bt", "bt_error", "snap"])
        with open(js, encoding="utf-8") as f:
            return rows, json.load(f)

    def assert_equal_to_program(self, r, rows, report):
        self.assertEqual(r["at"]["bt"].shape, (len(QUERIES),))
        for i, row in enumerate(rows):
            for column, name in ((3, "bt"), (4, "bt_error"), (5, "snap")):
                self.assertTrue(same_number(r["at"][name][i], float(row[column])), (i, name, r["at"][name][i], row))
        values = report["vertex_values"]
        for field in ("BT", "ET"):
            expected = [math.inf if v is None else v for v in values[field]]
            np.testing.assert_array_equal(r[field], expected)
        for key in ("input", "method", "spacing", "complex", "summary", "sources", "queries"):
            self.assertEqual(r[key], report[key], key)

    def test_arrays_and_files_equal_the_programs_csv(self):
        for extra, flag in (((), False), (("--no-border-ignition",), True)):
            with self.subTest(no_border_ignition=flag):
                rows, report = self.program("--sources", self.sources, *extra)
                self.assertEqual(report["sources"], 2)
                from_arrays = grassfire.burn3d(HINGE, spacing=0.125, sources=np.array(SOURCES, float),
                                               at=np.array(QUERIES, float), no_border_ignition=flag)
                self.assert_equal_to_program(from_arrays, rows, report)
                from_files = grassfire.burn3d(HINGE, spacing=0.125, sources=self.sources, at=self.at,
                                              no_border_ignition=flag)
                self.assert_equal_to_program(from_files, rows, report)

    def test_values_at_sources_vertices_and_snapped_points(self):
        r = grassfire.burn3d(HINGE, spacing=0.125, sources=SOURCES, at=QUERIES, no_border_ignition=True)
        at = r["at"]
        self.assertEqual(at["bt"][0], 0.125)   # a query at a source burns at its t0
        self.assertLessEqual(at["bt"][2], 0.25)  # vertex 1 is a source with t0 = 0.25
        vertex1 = int(np.flatnonzero(np.all(r["vertices"] == [2, 0, 0], axis=1))[0])
        self.assertEqual(at["bt"][2], r["BT"][vertex1])  # a query at a vertex: the vertex's BT
        np.testing.assert_array_equal(at["points"][1], [1, 1, 0])  # (1, 1, 0.5) snaps to the plane z = 0
        self.assertEqual(at["snap"][1], 0.5)
        located = grassfire.burn3d(HINGE, spacing=0.125, sources=SOURCES, at=[[1, 1, 0]], no_border_ignition=True)
        self.assertEqual(located["at"]["bt"][0], at["bt"][1])  # a snapped query has its located point's value
        self.assertEqual(located["at"]["snap"][0], 0)
        self.assertTrue(math.isclose(at["snap"][4], math.hypot(0.5, 0.25), rel_tol=1e-15))  # past (3, 0, 0)
        self.assertTrue(np.all(np.isinf(at["bt_error"])))  # discrete: an upper bound only
        # Only the sources burn. Vertex 0 = (0, 0, 0) and the first source share triangle 0,
        # so BT(0) = 0.125 + |(1, 0.5)| (the source at vertex 1 arrives at 0.25 + 2); the
        # discrete value is an upper bound, within about the spacing.
        exact = 0.125 + math.hypot(1, 0.5)
        self.assertGreaterEqual(at["bt"][6], exact * (1 - 1e-15))
        self.assertLessEqual(at["bt"][6], exact + 0.125)
        self.assertEqual(r["sources"], 2)
        self.assertEqual(r["queries"], len(QUERIES))

    def test_no_points_no_at_member(self):
        r = grassfire.burn3d(HINGE, spacing=0.125)
        self.assertNotIn("at", r)
        self.assertEqual((r["sources"], r["queries"]), (0, 0))


class Burn3dPointErrors(unittest.TestCase):
    def test_file_errors_have_the_programs_messages(self):
        with tempfile.TemporaryDirectory(prefix=f"grassfire_py_{os.getpid()}_") as tmp:
            sources, at = os.path.join(tmp, "s.csv"), os.path.join(tmp, "q.csv")
            write_csv(at, "x,y,z", [[0, 0, 0]])
            for text in ("x,y,z,t0\n0,0,0,0\n0,0,-0.5,1\n", "x,y,z\n0,0,0\n", "x,y,z,t0\n0,0,nan,0\n", ""):
                with open(sources, "w", encoding="utf-8") as f:
                    f.write(text)
                with self.subTest(sources=text):
                    expected = cli_error("burn3d", "tetrahedron", "--sources", sources, "--at", at)
                    with self.assertRaises(RuntimeError) as caught:
                        grassfire.burn3d("tetrahedron", sources=sources, at=at)
                    self.assertEqual(str(caught.exception), expected)
            expected = cli_error("burn3d", "tetrahedron", "--at", os.path.join(tmp, "missing.csv"))
            with self.assertRaises(RuntimeError) as caught:
                grassfire.burn3d("tetrahedron", at=os.path.join(tmp, "missing.csv"))
            self.assertEqual(str(caught.exception), expected)

    def test_array_errors(self):
        with self.assertRaises(RuntimeError) as caught:
            grassfire.burn3d("tetrahedron", sources=[[0, 0, 0, 0], [0, 0, -0.5, 1]])
        self.assertEqual(str(caught.exception), "sources:2: source (0, 0, -0.5) does not lie on the complex "
                                                "(its nearest point is at distance 0.5)")
        with self.assertRaisesRegex(ValueError, r"sources: not a CSV path or an \(n, 4\) array"):
            grassfire.burn3d("tetrahedron", sources=[[0, 0, 0]])
        with self.assertRaisesRegex(ValueError, r"at: not a CSV path or an \(n, 3\) array"):
            grassfire.burn3d("tetrahedron", at=np.zeros((2, 4)))
        with self.assertRaisesRegex(ValueError, "at:2: a value is not a finite number"):
            grassfire.burn3d("tetrahedron", at=[[0, 0, 0], [0, math.nan, 0]])


if __name__ == "__main__":
    unittest.main()
