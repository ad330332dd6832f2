"""Inverse distance to the goal in Python, as the native plugin heuristic/distance, bit for bit.

    acoplan --heuristic python --heuristic.class distance:Distance --heuristic.path examples/python
"""
import numpy as np


class Distance:
    def __init__(self, min_distance=0.01):
        self.min_distance = min_distance

    def compute(self, context, eta):
        graph = context.graph
        # Eigen's norm of a 3-vector: sqrt((dx^2 + dy^2) + dz^2), summed in this order.
        d = graph.positions[graph.targets] - graph.positions[context.goal]
        squares = d * d
        distance = np.sqrt((squares[:, 0] + squares[:, 1]) + squares[:, 2])
        eta[:] = 1.0 / np.maximum(distance, self.min_distance)
