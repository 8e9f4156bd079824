"""The Python twins of the program's commands: prune2d, match2d, complex, curves3d, paths3d,
prune3d, member by member against the program's --json; array and object inputs against the
same data as files; errors with the program's messages; the documented examples (doctest).
(The GIL and progress: test_long_calls.py.)
"""
import doctest
import json
import os
import tempfile
import types
import unittest

import numpy as np

import grassfire
from support import PROJECT_DATA, TEST_DATA, cli_error, cli_json, json_number, run_cli, same_number, write_png_gray

CUBE = os.path.join(PROJECT_DATA, "meshes", "cube.off")
BALLS = os.path.join(TEST_DATA, "3d", "three_balls.cin")


def read_off(path):
    """V, F of a small OFF file (triangles and quads split as fans)."""
    with open(path, encoding="utf-8") as f:
        tokens = [line.split("#")[0].split() for line in f]
    tokens = [t for t in tokens if t]
    assert tokens[0][0] == "OFF"
    nv, nf = int(tokens[1][0]), int(tokens[1][1])
    vertices = np.array([[float(x) for x in t[:3]] for t in tokens[2:2 + nv]])
    faces = []
    for t in tokens[2 + nv:2 + nv + nf]:
        ids = [int(x) for x in t[1:1 + int(t[0])]]
        faces += [[ids[0], ids[i], ids[i + 1]] for i in range(1, len(ids) - 1)]
    return vertices, np.array(faces)


def plain(x):
    """x with numpy arrays and scalars as lists and Python numbers (to compare with JSON)."""
    if isinstance(x, dict):
        return {k: plain(v) for k, v in x.items()}
    if isinstance(x, (np.ndarray, np.generic)):
        return x.tolist()
    return x


def as_columns(doc, key):
    """doc with its array of objects doc[key] as the module gives it: a dict of columns."""
    out = dict(doc)
    out[key] = {k: [o[k] for o in doc[key]] for k in doc[key][0]}
    return out


def assert_columns_equal(test, columns, objects, keys):
    for key in keys:
        test.assertEqual(len(columns[key]), len(objects), key)
        for i, o in enumerate(objects):
            test.assertTrue(same_number(columns[key][i], json_number(o[key])), (key, i, columns[key][i], o[key]))


class DocumentedExamples(unittest.TestCase):
    def test_every_documented_example_runs(self):
        suite = doctest.DocTestSuite(grassfire)
        names = {t.id().split(".")[-1] for t in suite}
        for f in ("prune2d", "match2d", "medial3d", "burn3d", "complex", "curves3d", "paths3d", "prune3d",
                  "validate", "shapes"):
            self.assertIn(f, names)
        result = unittest.TextTestRunner(verbosity=0).run(suite)
        self.assertTrue(result.wasSuccessful(), result.failures)


class TwinsEqualProgram(unittest.TestCase):
    def test_prune2d(self):
        r = grassfire.prune2d("blunt-sharp", et="0.05", relative=True, st="0.3", topology=True, samples=600)
        j = cli_json("prune2d", "blunt-sharp", "--et", "0.05", "--relative", "--st", "0.3", "--topology",
                     "--samples", "600")
        self.assertEqual(r["thresholds"], j["thresholds"])
        assert_columns_equal(self, r["nodes"], j["nodes"], ["x", "y", "R", "edf", "et", "st"])
        assert_columns_equal(self, r["edges"], j["edges"], ["u", "v", "length", "from", "to"])

    def test_match2d(self):
        r = grassfire.match2d("rectangle", "rectangle-bump", samples=40, signature="curvature")
        j = cli_json("match2d", "rectangle", "rectangle-bump", "--samples", "40", "--signature", "curvature")
        for key in ("cost", "offset", "stretch_steps", "samples"):
            self.assertEqual(r[key], j[key], key)
        self.assertEqual(r["correspondence"].tolist(), j["correspondence"])
        self.assertEqual(r["path"].tolist(), j["path"])

    def test_validate(self):
        for shape in ("hole", "blunt-sharp", os.path.join(PROJECT_DATA, "shapes2d", "LICENSE.md")):
            if shape.endswith(".md"):
                continue
            r = grassfire.validate(shape)
            j = cli_json("validate", shape)
            self.assertEqual(plain(r), as_columns(j, "rings"))
        ring = [[0, 0], [3, 0], [3, 0], [3, 2], [0, 2]]  # clockwise-free, one repeated vertex
        with tempfile.TemporaryDirectory() as tmp:
            wkt = os.path.join(tmp, "rect.wkt")
            with open(wkt, "w", encoding="utf-8") as f:
                f.write("POLYGON ((0 0, 3 0, 3 0, 3 2, 0 2, 0 0))")
            j = cli_json("validate", wkt)
        r = plain(grassfire.validate(np.array(ring, dtype=float), name="rect"))
        for key in ("vertices", "orientation", "signed_area"):  # the WKT also counts its closing vertex as given
            self.assertEqual(r["rings"][key], as_columns(j, "rings")["rings"][key], key)
        self.assertEqual((r["area"], r["rings"]["input_vertices"], r["rings"]["vertices"]), (6.0, [5], [4]))

    def test_shapes(self):
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "list.json")
            code, _, err = run_cli("shapes", "--list-json", out)
            self.assertEqual(code, 0, err)
            with open(out, encoding="utf-8") as f:
                self.assertEqual(plain(grassfire.shapes()), as_columns(json.load(f), "shapes"))
        code, text, err = run_cli("shapes", "--json", "rectangle")
        self.assertEqual(code, 0, err)
        expected = json.loads(text)
        got = plain(grassfire.shapes("rectangle"))
        self.assertEqual(set(got), set(expected))
        for key in expected:
            if not isinstance(expected[key], (list, dict)):
                self.assertEqual(got[key], expected[key], key)
        with self.assertRaises(ValueError):
            grassfire.shapes("no-such-shape")

    def test_complex(self):
        r = grassfire.complex("y-junction")
        j = cli_json("complex", "y-junction")
        self.assertEqual(len(r["triangles"]), len(j["triangles"]))
        self.assertEqual(len(r["vertices"]), len(j["vertices"]))
        self.assertEqual(r["counts"]["triangles"], len(j["triangles"]))

    def test_curves3d(self):
        r = grassfire.curves3d("annulus", spacing=0.25)
        j = cli_json("curves3d", "annulus", "--spacing", "0.25")
        self.assertEqual(plain(r["betti"]), j["betti"])
        self.assertEqual(plain(r["axis_betti"]), j["axis_betti"])
        assert_columns_equal(self, r["nodes"], j["nodes"], ["x", "y", "z", "R", "bt", "et"])
        assert_columns_equal(self, r["edges"], j["edges"], ["u", "v", "length"])
        self.assertEqual(r["points"].shape, (len(j["nodes"]), 3))
        self.assertEqual(r["segments"].tolist(), [[e["u"], e["v"]] for e in j["edges"]])

    def test_paths3d(self):
        r = grassfire.paths3d("tube", from_="vertices", spacing=0.5)
        j = cli_json("paths3d", "tube", "--from", "vertices", "--spacing", "0.5")
        assert_columns_equal(self, r["paths"], j["paths"], ["bt", "length"])
        for mine, theirs in zip(r["paths"]["points"], j["paths"]):
            self.assertEqual(np.asarray(mine).tolist(), theirs["points"])

    def test_prune3d(self):
        for method in ("exact", "discrete"):
            r = grassfire.prune3d("box:6:4:2", et="0.3", relative=True, method=method)
            j = cli_json("prune3d", "box:6:4:2", "--et", "0.3", "--relative", "--method", method)
            for key in ("axis", "refined", "removed", "pruned", "thresholds", "uncertified"):
                self.assertEqual(plain(r[key]), j[key], key)
            self.assertEqual(plain(r["pruned"]["betti"]), plain(r["axis"]["betti"]))
            for k, name in enumerate("xyz"):
                self.assertEqual(r["vertices"][:, k].tolist(), j["vertex_values"][name])
            for name in ("R", "BT", "ET"):
                assert_columns_equal(self, {name: r[name]}, [{name: x} for x in j["vertex_values"][name]], [name])
            self.assertEqual(r["triangles"].tolist(), j["triangles"])


class ArrayInputs(unittest.TestCase):
    def test_mesh_arrays_and_objects_equal_the_file(self):
        from_file = grassfire.medial3d(CUBE)
        V, F = read_off(CUBE)
        for given in ((V, F), [V, F], types.SimpleNamespace(vertices=V, faces=F)):
            r = grassfire.medial3d(given, name="cube")
            self.assertEqual(r["input"], "cube")
            self.assertEqual(r["vertices"].tolist(), from_file["vertices"].tolist())
            self.assertEqual(r["triangles"].tolist(), from_file["triangles"].tolist())
        b = grassfire.burn3d((V, F), method="exact")
        self.assertEqual(b["BT"].tolist(), grassfire.burn3d(CUBE, method="exact")["BT"].tolist())
        p = grassfire.prune3d((V, F), et=0.5, relative=True)
        self.assertEqual(plain(p["pruned"]["betti"]), plain(p["axis"]["betti"]))

    def test_ball_arrays_equal_the_ball_file(self):
        balls = np.array([[0, 0, 0, 1], [1.5, 0, 0, 0.5], [0, 2, 0, 1.5]])
        r, f = grassfire.medial3d(balls), grassfire.medial3d(BALLS)
        self.assertEqual(r["vertices"].tolist(), f["vertices"].tolist())
        self.assertEqual(r["R"].tolist(), f["R"].tolist())

    def test_bad_arrays_name_the_array(self):
        V, F = read_off(CUBE)
        with self.assertRaises(ValueError) as e:
            grassfire.medial3d((V[:, :2], F), name="flat")
        self.assertIn("flat", str(e.exception))
        bad = F.copy()
        bad[0, 0] = 99
        with self.assertRaises(Exception) as e:
            grassfire.burn3d((V, bad), name="broken")
        self.assertIn("broken", str(e.exception))
        self.assertNotIn("grassfire_py_", str(e.exception))

    def test_shapely_like_polygons_and_boolean_images(self):
        ring = [(0, 0), (4, 0), (4, 2), (0, 2), (0, 0)]
        polygon = types.SimpleNamespace(exterior=types.SimpleNamespace(coords=ring), interiors=[])
        a = grassfire.prune2d(polygon, et=0.1, samples=400)
        b = grassfire.prune2d(np.array(ring[:-1], float), et=0.1, samples=400)
        self.assertEqual(a["nodes"]["x"].tolist(), b["nodes"]["x"].tolist())
        mask = np.zeros((12, 16), bool)
        mask[3:9, 2:14] = True
        with tempfile.TemporaryDirectory(prefix=f"grassfire_py_{os.getpid()}_") as tmp:
            png = os.path.join(tmp, "rect.png")
            write_png_gray(png, [[0 if m else 255 for m in row] for row in mask])
            from_image = grassfire.edf2d(mask, exact=True)
            from_file = grassfire.edf2d(png, exact=True)
        self.assertEqual(from_image["nodes"]["x"].tolist(), from_file["nodes"]["x"].tolist())


class Errors(unittest.TestCase):
    def test_messages_are_the_programs(self):
        with self.assertRaises(ValueError) as e:
            grassfire.prune3d("tube")
        self.assertEqual(str(e.exception), cli_error("prune3d", "tube", "--method", "exact"))
        with self.assertRaises(ValueError) as e:
            grassfire.prune3d("tube", st=2)
        self.assertEqual(str(e.exception), cli_error("prune3d", "tube", "--st", "2"))
        with self.assertRaises(Exception) as e:
            grassfire.curves3d("no-such-file.off")
        self.assertEqual(str(e.exception), cli_error("curves3d", "no-such-file.off"))
        with self.assertRaises(Exception) as e:
            grassfire.validate(np.array([[0, 0], [2, 2], [2, 0], [0, 2]], dtype=float), name="bowtie")
        with tempfile.TemporaryDirectory() as tmp:
            wkt = os.path.join(tmp, "bowtie.wkt")
            with open(wkt, "w", encoding="utf-8") as f:
                f.write("POLYGON ((0 0, 2 2, 2 0, 0 2, 0 0))")
            self.assertEqual(str(e.exception).replace("bowtie", "X"), cli_error("validate", wkt).replace(wkt, "X"))
        with self.assertRaises(ValueError) as e:
            grassfire.paths3d("tube", from_="nowhere")
        self.assertEqual(str(e.exception), cli_error("paths3d", "tube", "--from", "nowhere"))


if __name__ == "__main__":
    unittest.main()
