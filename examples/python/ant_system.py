"""Ant System in Python: the same update as the native plugin update/ant_system, bit for bit.

    acoplan --update python --update.class ant_system:AntSystem --update.path examples/python

The parameters are the object's attributes: AntSystem() has the native plugin's defaults; for
others, name an object made with them (--update.class my_module:fast, fast = AntSystem(rho=0.5)).
"""
import numpy as np


class AntSystem:
    def __init__(self, rho=0.3, q=1.0):
        self.rho = rho
        self.q = q

    def update(self, context, iteration, tau):
        # The operations of aco::evaporate and aco::deposit, in their order: every edge times
        # (1 - rho), then Q / L added edge by edge, ants in ant order. np.add.at adds one index
        # at a time, in order, so an edge an ant walked twice gets both deposits as in C++.
        tau *= 1.0 - self.rho
        arrived = [ant for ant in iteration.ants if ant.arrived]
        if not arrived:
            return
        edges = np.concatenate([ant.edges for ant in arrived])
        amounts = np.concatenate([np.full(len(ant.edges), self.q / ant.length) for ant in arrived])
        np.add.at(tau, edges, amounts)
