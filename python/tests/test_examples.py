"""The examples of examples/python run as their headers say, and say what they should."""
import os
import subprocess
import sys

from conftest import SOURCE

EXAMPLES = SOURCE / "examples" / "python"


def run(script, *args, cwd):
    out = subprocess.run([sys.executable, str(EXAMPLES / script), *map(str, args)], cwd=cwd, capture_output=True,
                         text=True, env={**os.environ, "MPLBACKEND": "Agg"}, timeout=600)
    assert out.returncode == 0, out.stderr
    return out.stdout


def test_plan_on_a_numpy_grid_and_plot_it(tmp_path):
    printed = run("plan_numpy_grid.py", tmp_path / "grid.png", cwd=tmp_path)
    assert printed.startswith("<aco.Result length")
    assert (tmp_path / "grid.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_the_python_best_worst_ant_system_against_max_min_in_a_study(tmp_path):
    printed = run("compare_bwas.py", tmp_path / "bwas.db", cwd=tmp_path)
    assert "ran 20 trials, 0 failed" in printed
    assert "bwas (python)" in printed and "max-min" in printed
    assert "p_holm" in printed
