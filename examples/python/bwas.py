"""The Best-Worst Ant System update (Cordón, Fernández de Viana, Herrera 2000), written in Python
for the python bridge plugin: `update=BestWorstAntSystem()` in aco.plan(), or
`--update python --update.class bwas:BestWorstAntSystem` in any host (with this folder on
PYTHONPATH or given as --update.path).

After every iteration:
  1. evaporate:            tau <- (1 - rho) tau
  2. best-so-far deposit:  tau_e += q / L_best on the edges of the best path so far
  3. worst penalty:        tau_e <- (1 - rho) tau_e once more on the edges of the iteration's
                           worst arrived ant that are not on the best path so far
  4. mutation:             each edge, with probability `mutation`, moves by
                           +-(iteration / iterations) * sigma * mean tau on the best path
                           (a random sign), never below tau_min
The random draws come from the run's seed and the iteration, so results are reproducible.
The paper's restart on stagnation is left out (the engine has its own `stagnation` key).
"""
import numpy as np


class BestWorstAntSystem:
    def __init__(self, rho=0.3, q=1.0, mutation=0.3, sigma=0.4, tau_min=1e-6):
        self.rho, self.q, self.mutation, self.sigma, self.tau_min = rho, q, mutation, sigma, tau_min

    def update(self, context, iteration, tau):
        tau *= 1.0 - self.rho
        best = iteration.best_so_far
        if best is None:
            return
        np.add.at(tau, best.edges, self.q / best.length)
        arrived = [ant for ant in iteration.ants if ant.arrived]
        if arrived:
            worst = max(arrived, key=lambda ant: ant.length)
            penalised = np.setdiff1d(worst.edges, best.edges)
            tau[penalised] *= 1.0 - self.rho
        rng = np.random.default_rng([context.seed, context.iteration])
        mutated = rng.random(tau.size) < self.mutation
        step = (context.iteration + 1) / context.max_iterations * self.sigma * tau[best.edges].mean()
        tau[mutated] += np.where(rng.random(mutated.sum()) < 0.5, -step, step)
        np.maximum(tau, self.tau_min, out=tau)
