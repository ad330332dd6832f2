#pragma once
// What the engine may know of the optional hooks' defaults (strategies.cpp), inside libaco only.

namespace aco {

// Set by DeadlockPolicy's default after_iteration(), which writes nothing, on the thread that ran
// it. The engine clears it before the call and, when it is set after, skips the pass that checks
// the pheromone: on large maps a pass over every edge costs as much as the ants' iteration. (An
// override that calls this default too is checked only after the update, whose message would
// then name the update.)
extern thread_local bool ran_default_after_iteration;

}  // namespace aco
