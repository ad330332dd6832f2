"""Regenerates the figures the pages of docs/ quote, and the pictures in docs/images/.

Each figure lives in a region of a tracked Markdown file between two markers,

    <!-- figures:NAME begin (tools/figures.sh SECTION) -->
    ...
    <!-- figures:NAME end -->

and a section replaces only its own regions, so running one section never touches another's
figures. A figure inside a sentence is an inline region on one line,

    about <!-- figures:NAME inline (STAMP) -->2 s<!-- figures:NAME end --> on 2 threads

whose short stamp the section rewrites with it. Every region starts with a stamp: the machine (cores, CPU model), the load average at
the section's start and end, the date, the commit and the exact commands, because times hold only
for the machine and the load they were taken on (ratios travel better, and are quoted where they
can be). The numbers are always read from the tools' own output, never typed.

Run through tools/figures.sh (which builds first); `tools/figures.sh --list` lists the sections.
"""
# The package: project.py (paths, the error), regions.py (the markers), run.py (running tools, the
# stamps), sections.py (the registry), formatting.py, bench_output.py (aco_bench's text), and a
# module per group of sections, imported here. Each registers its sections as it is imported: in
# this order --list shows them and a run without sections runs them.
from . import benchmarks, experiments, ompl, durations, pictures, large_maps, large_2048, voxel, voxel_large, ros, explorers  # noqa: F401
