"""Uniform initial pheromone in Python, as the native plugin init/uniform (tau0 = 8).

    acoplan --init python --init.class uniform:Uniform --init.path examples/python
"""


class Uniform:
    def __init__(self, tau0=8.0):
        self.tau0 = tau0

    def initialize(self, context, tau):
        tau.fill(self.tau0)
