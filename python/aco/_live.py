"""Python objects given to aco.plan() as plugins (update=MyUpdate()), for the length of the call:
the python bridge plugin reaches each as ``aco._live:<name>``."""
