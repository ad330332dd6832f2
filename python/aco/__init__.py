"""Ant-colony path planning with runtime plugins, from Python.

    import numpy as np, aco
    grid = np.zeros((20, 20), dtype=bool); grid[5:15, 10] = True
    result = aco.plan(grid, (0, 0), (19, 19), update="max_min", update_rho=0.1)
    result.path, result.length, result.gap_percent

Maps: aco.Map (numpy arrays, map files), aco.load_scenarios() (Moving AI .scen). Runs: aco.plan(),
aco.astar(); their keywords: aco.run_keys(). Plugins: aco.plugins(), aco.describe(),
aco.add_plugin_dir(), aco.presets(); a slot may be a Python object (update=MyUpdate()), run inside
the native colony. Studies: aco.run_experiment(), aco.read_database(); aco.stats has the report's
statistics. Errors raise aco.Error (a ValueError) with the command line's message; a plugin's
failure raises aco.PluginError (an aco.Error), from a Python hook's own exception.
Pictures: aco.plot(), plan(svg=...); results and maps show themselves in Jupyter. Simulation:
aco.simulate() (acosim). aco.__version__ is the framework's.
"""
from . import _aco, stats
from ._aco import PluginError
from ._catalog import add_plugin_dir, describe, plugins, presets, run_keys
from ._pictures import plot
from ._planning import Error, Map, Result, Scenario, astar, load_scenarios, plan
from ._simulation import Simulation, simulate
from ._studies import read_database, run_experiment

__version__: str = _aco.__version__

__all__ = ["Error", "PluginError", "Map", "Result", "Scenario", "plan", "astar", "load_scenarios", "run_keys",
           "plugins", "describe", "add_plugin_dir", "presets", "run_experiment", "read_database", "stats", "plot",
           "simulate", "Simulation"]
