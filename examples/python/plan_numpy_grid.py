"""Plan on an occupancy grid made in numpy, and plot the path with matplotlib.

    PYTHONPATH=build/release/python python3 examples/python/plan_numpy_grid.py grid.png
"""
import sys

import matplotlib

matplotlib.use("Agg")  # write a file; no display needed
import matplotlib.pyplot as plt
import numpy as np

import aco

# Four rooms of a 60 x 40 grid, joined by doors: True is blocked, grid[y, x] is cell (x, y).
grid = np.zeros((40, 60), dtype=bool)
grid[:, 30] = True
grid[20, :] = True
for y, x in [(10, 30), (30, 30), (20, 12), (20, 47)]:
    grid[y, x] = False

result = aco.plan(grid, start=(2, 2), goal=(57, 37), seed=1)
print(result)
reference = aco.astar(grid, (2, 2), (57, 37))

figure, (left, right) = plt.subplots(1, 2, figsize=(11, 4))
left.imshow(grid, cmap="gray_r", origin="upper")
left.plot(reference.path[:, 0], reference.path[:, 1], "--", color="tab:green", label=f"A* {reference.length:.2f}")
left.plot(result.path[:, 0], result.path[:, 1], color="tab:red", label=f"colony {result.length:.2f}")
left.legend(loc="lower left")
left.set_title(f"preset {result.preset}, seed {result.seed}")
right.plot(result.convergence, label="best so far")
right.axhline(result.optimal_length, color="tab:green", linestyle="--", label="optimum")
right.set_xlabel("iteration")
right.set_ylabel("length")
right.legend()
figure.tight_layout()
figure.savefig(sys.argv[1] if len(sys.argv) > 1 else "grid.png", dpi=80)
