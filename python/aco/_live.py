"""Python objects given to aco.plan() or aco.run_experiment() as plugins (update=MyUpdate()), for the length of the call:
the python bridge plugin reaches each as ``aco._live:<name>``."""
