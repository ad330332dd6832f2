"""tools/figures/'s region replacement: a run replaces only its sections' regions."""
import sys
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
import figures  # noqa: E402  (registers every section)
from figures import bench_output, regions  # noqa: E402
from figures.project import ROOT, FiguresError  # noqa: E402

PAGE = """# Title
intro
<!-- figures:engine begin (tools/figures.sh engine) -->
old engine table
<!-- figures:engine end -->
between
<!-- figures:plugins begin (tools/figures.sh plugins) -->
old plugin table
<!-- figures:plugins end -->
after
"""


class ReplaceRegions(unittest.TestCase):
    def test_a_region_is_replaced_and_the_rest_left_as_it_was(self):
        out = regions.replace_regions(PAGE, {"engine": "new engine table\nsecond line"}, "engine", "README.md")
        self.assertEqual(out, PAGE.replace("old engine table", "new engine table\nsecond line"))
        self.assertIn("old plugin table", out)

    def test_replacing_twice_gives_the_same_page(self):
        once = regions.replace_regions(PAGE, {"plugins": "\n\nnew\n\n"}, "plugins", "README.md")
        self.assertEqual(regions.replace_regions(once, {"plugins": "new"}, "plugins", "README.md"), once)
        self.assertIn("<!-- figures:plugins begin (tools/figures.sh plugins) -->\nnew\n<!-- figures:plugins end -->", once)

    def test_a_missing_region_is_an_error_naming_the_section_and_the_markers(self):
        with self.assertRaises(FiguresError) as caught:
            regions.replace_regions(PAGE, {"large": "x"}, "large", "README.md")
        message = str(caught.exception)
        self.assertIn("README.md: no region 'figures:large' for section 'large'", message)
        self.assertIn("<!-- figures:large begin (tools/figures.sh large) -->", message)
        self.assertIn("<!-- figures:large end -->", message)

    def test_a_region_without_its_end_or_twice_is_an_error(self):
        unclosed = PAGE.replace("<!-- figures:engine end -->\n", "")
        with self.assertRaisesRegex(FiguresError, "'figures:engine' of section 'engine' has 1 begin and 0 end"):
            regions.replace_regions(unclosed, {"engine": "x"}, "engine", "README.md")
        with self.assertRaisesRegex(FiguresError, "has 2 begin and 2 end"):
            regions.replace_regions(PAGE + PAGE, {"engine": "x"}, "engine", "README.md")

    def test_a_name_that_starts_another_regions_name_is_not_confused_with_it(self):
        page = PAGE.replace("figures:plugins", "figures:engine-plugins")
        out = regions.replace_regions(page, {"engine": "new"}, "engine", "README.md")
        self.assertIn("old plugin table", out)
        self.assertNotIn("old engine table", out)

    def test_an_inline_region_is_replaced_in_its_sentence_with_its_stamp(self):
        page = ("It takes <!-- figures:t inline (tools/figures.sh durations) -->about 2 s<!-- figures:t end --> "
                "on 2 threads.\n" + PAGE)
        out = regions.replace_regions(page, {"t": "about 3 s"}, "durations", "README.md", "STAMP")
        self.assertEqual(out, page.replace("(tools/figures.sh durations) -->about 2 s", "(STAMP) -->about 3 s"))
        self.assertEqual(regions.replace_regions(out, {"t": "about 3 s"}, "durations", "README.md", "STAMP"), out)
        start, end = regions.find_region(out, "t", "durations", "README.md")
        self.assertEqual(out[start:end], "about 3 s")
        with self.assertRaisesRegex(FiguresError, "inline region 'figures:t' is not one line"):
            regions.replace_regions(page, {"t": "two\nlines"}, "durations", "README.md")
        with self.assertRaisesRegex(FiguresError, "'figures:t' of section 'durations' is there 2 times"):
            regions.replace_regions(page + page, {"t": "x"}, "durations", "README.md")

    def test_every_section_names_its_regions_in_the_tracked_files(self):
        # The tracked pages (docs/*.md, data/experiments/README.md) hold every region a section writes.
        for section in figures.sections.SECTIONS.values():
            for file, region in section.regions:
                regions.find_region((ROOT / file).read_text(), region, section.name, str(file))


class Parsing(unittest.TestCase):
    def test_aco_bench_classic_output_is_read(self):
        text = """== classic map1 ==
update        median ms     min ms  ns/ant step  mean length
ant_system        3.100      2.900         21.0      35.0600
max_min           4.800      4.600         27.0      34.3900
acs               4.300      4.100         26.0      34.5000

== plugins ==
slot/plugin                   ns/ant step    ratio  mean length
(baseline)                           21.0     1.00      35.0600
heuristic/direction                  33.0     1.57      35.5000
smoother/prune                    1.50 us per call on the best map1 path (25 cells -> 6 waypoints)
"""
        c = bench_output.parse_classic(text)
        self.assertEqual(c["updates"]["max_min"]["median"], 4.8)
        self.assertEqual(c["plugins"]["heuristic/direction"]["ratio"], 1.57)
        self.assertEqual(c["prune_cells"], 25)
        with self.assertRaisesRegex(FiguresError, "aco_bench --only classic: its output has changed"):
            bench_output.parse_classic(text.replace("acs ", "xyz "))

    def test_aco_bench_terrain_and_fireworks_output_is_read(self):
        text = """epf20     314.40 plain           1       3.80       3.60         30.1       329.41
epf20     314.40 plain           2       4.60       4.10         31.0       329.41
results with 1 and 2 threads identical (last seed: path, length, steps, curve, pheromone): yes
median 46.90 ms, min 45.00 ms, 26.0 us per evaluation, mean best length 45.5500
"""
        t = bench_output.parse_terrain(text)
        self.assertEqual([r["threads"] for r in t["rows"]], [1, 2])
        self.assertEqual(t["fireworks"]["median"], 46.9)
        self.assertEqual(t["fireworks"]["length"], 45.55)
        self.assertTrue(t["identical"])
        self.assertFalse(bench_output.parse_terrain(text.replace(": yes", ": NO"))["identical"])


if __name__ == "__main__":
    unittest.main()
