"""grassfire.edf2d against `grassfire edf2d --json` on test shapes."""
import os
import tempfile
import unittest

import numpy as np

import grassfire
from support import PROJECT_DATA, TEST_DATA, cli_error, cli_json, json_number, same_number, write_png_gray


class Edf2dEqualsProgram(unittest.TestCase):
    def assert_same_document(self, result, document):
        """Every member of the program's document, in the module's form (columns, numpy)."""
        self.assertEqual(set(result), set(document))
        for key in ("format", "version", "shape", "variant", "samples", "error_bound", "certification"):
            self.assertEqual(result[key], document[key], key)
        nodes, edges = result["nodes"], result["edges"]
        self.assertEqual(set(nodes), set(document["nodes"][0]))
        for column, values in nodes.items():
            self.assertIsInstance(values, np.ndarray, column)
            self.assertEqual(len(values), len(document["nodes"]))
            for got, node in zip(values, document["nodes"]):
                self.assertTrue(same_number(got, json_number(node[column])), (column, got, node[column]))
        self.assertEqual(list(edges["u"]), [e["u"] for e in document["edges"]])
        self.assertEqual(list(edges["v"]), [e["v"] for e in document["edges"]])
        self.assertEqual(list(edges["length"]), [e["length"] for e in document["edges"]])
        self.assertEqual(list(edges["kind"]), [e["kind"] for e in document["edges"]])
        self.assert_same_value(result["ema"], document["ema"])
        if "pr_max" in document:
            self.assert_same_value(result["pr_max"], document["pr_max"])

    def assert_same_value(self, got, expected):
        if isinstance(expected, dict):
            self.assertEqual(set(got), set(expected))
            for k in expected:
                self.assert_same_value(got[k], expected[k])
        elif isinstance(expected, list):
            self.assertEqual(len(got), len(expected))
            for g, e in zip(got, expected):
                self.assert_same_value(g, e)
        elif isinstance(expected, (int, float)) or expected in ("inf", "-inf", None):
            self.assertTrue(same_number(got, json_number(expected)), (got, expected))
        else:
            self.assertEqual(got, expected)

    def test_builtin_shapes_exact_and_sampled(self):
        for name in ("rectangle", "hole", "branches"):
            for exact in (False, True):
                with self.subTest(shape=name, exact=exact):
                    args = [name, "--samples", "500"] + (["--exact"] if exact else [])
                    self.assert_same_document(grassfire.edf2d(name, samples=500, exact=exact), cli_json("edf2d", *args))

    def test_dataset_file_and_dissertation_variant(self):
        path = os.path.join(PROJECT_DATA, "shapes2d", "Bone-1.json")
        self.assert_same_document(grassfire.edf2d(path, exact=True), cli_json("edf2d", path, "--exact"))
        self.assert_same_document(grassfire.edf2d(path, samples=800, variant="dissertation"),
                                  cli_json("edf2d", path, "--samples", "800", "--variant", "dissertation"))

    def test_hole_ema_is_cycles_with_infinite_edf(self):
        r = grassfire.edf2d("hole", exact=True)
        self.assertEqual(r["ema"]["kind"], "cycles")
        on_cycle = r["ema"]["nodes"]
        self.assertGreater(len(on_cycle), 2)
        self.assertTrue(np.all(np.isinf(r["nodes"]["edf"][on_cycle])))
        self.assertFalse(np.any(np.isinf(np.delete(r["nodes"]["edf"], on_cycle))))

    def test_arrays_give_the_shape_the_file_gives(self):
        with tempfile.TemporaryDirectory(prefix=f"grassfire_py_{os.getpid()}_") as tmp:
            path = os.path.join(tmp, "square_hole.wkt")
            with open(path, "w", encoding="utf-8") as f:
                f.write("POLYGON ((0 0, 8 0, 8 6, 0 6), (2 2, 2 4, 5 4, 5 2))")
            from_file = grassfire.edf2d(path, exact=True)
        outer = np.array([[0, 0], [8, 0], [8, 6], [0, 6]], dtype=float)
        hole = np.array([[2, 2], [2, 4], [5, 4], [5, 2]], dtype=float)
        from_arrays = grassfire.edf2d([outer, hole], exact=True, name="square_hole")
        for column in from_file["nodes"]:
            np.testing.assert_array_equal(from_arrays["nodes"][column], from_file["nodes"][column])
        self.assertEqual(from_arrays["shape"], "square_hole")
        # One ring as a single (n, 2) array, listed clockwise: normalized like a file.
        one = grassfire.edf2d(outer[::-1], exact=True)
        self.assertEqual(one["ema"]["kind"], "point")
        # x, y of an EMA inside an edge are interpolated doubles, for display.
        self.assertAlmostEqual(one["ema"]["x"], 4.0, places=12)
        self.assertAlmostEqual(one["ema"]["y"], 3.0, places=12)

    def test_image_file(self):
        rows = [[255] * 12 for _ in range(9)]
        for y in range(2, 7):
            for x in range(2, 10):
                rows[y][x] = 0
        with tempfile.TemporaryDirectory(prefix=f"grassfire_py_{os.getpid()}_") as tmp:
            path = os.path.join(tmp, "bar.png")
            write_png_gray(path, rows)
            self.assert_same_document(grassfire.edf2d(path, exact=True), cli_json("edf2d", path, "--exact"))
            r = grassfire.edf2d(path, exact=True, image={"contour": "marching-squares"})
            self.assert_same_document(r, cli_json("edf2d", path, "--exact", "--contour", "marching-squares"))
        # The 8 x 5 pixel bar is the rectangle [2, 10] x [2, 7] (y up): its EMA is the centre.
        self.assertAlmostEqual(r["ema"]["x"], 6.0, places=12)
        self.assertAlmostEqual(r["ema"]["y"], 4.5, places=12)


class Edf2dErrors(unittest.TestCase):
    def test_same_messages_as_the_program(self):
        files = ("bowtie.wkt", "nan.json", "holes_touch.wkt", "syntax_error.wkt", "empty.json")
        cases = ["nope", "/nonexistent/shape.json"] + [os.path.join(TEST_DATA, "shapes", f) for f in files]
        for shape in cases:
            with self.subTest(shape=shape):
                expected = cli_error("edf2d", shape)
                with self.assertRaises((ValueError, RuntimeError)) as caught:
                    grassfire.edf2d(shape)
                self.assertEqual(str(caught.exception), expected)

    def test_bad_arrays_and_options(self):
        with self.assertRaisesRegex(RuntimeError, "bowtie: ring 0 \\(outer\\)"):
            grassfire.edf2d(np.array([[0, 0], [1, 1], [1, 0], [0, 1]], dtype=float), name="bowtie")
        with self.assertRaisesRegex(ValueError, "not an \\(n, 2\\) array"):
            grassfire.edf2d(np.zeros((4, 3)))
        with self.assertRaisesRegex(RuntimeError, "coordinate"):
            grassfire.edf2d(np.array([[0, 0], [1, np.nan], [0, 1]]))
        with self.assertRaisesRegex(ValueError, "variant must be"):
            grassfire.edf2d("rectangle", variant="fast")
        with self.assertRaisesRegex(ValueError, "option --connectivity must be 4 or 8"):
            grassfire.edf2d("rectangle", image={"connectivity": 6})


if __name__ == "__main__":
    unittest.main()
