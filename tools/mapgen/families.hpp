// The map families of aco_mapgen --benchmark: random, room, maze, cave and hall maps in the style
// of the Moving AI families, and the building families (office plans, 8room-like rooms, rooms with
// doors of several widths) that the recommended pipeline's worst runs came from. Each takes its
// random draws from `rng` only, so a seed gives the same map on every machine.
#pragma once

#include <string>

#include "aco/map.hpp"
#include "aco/rng.hpp"

namespace mapgen {

// Each cell blocked with probability `density`.
aco::OccupancyGrid random_map(int size, double density, aco::Rng& rng, const std::string& name);

// Square rooms of `room` cells (walls included) on a grid; a spanning tree of doors (random
// depth-first order) keeps every room reachable, and every other wall has a door with
// probability `extra_doors`. A door is one free cell at a random place along the wall.
aco::OccupancyGrid room_map(int size, int room, double extra_doors, aco::Rng& rng, const std::string& name);

// A maze with corridors `corridor` cells wide and one-cell walls: a perfect maze (random
// depth-first backtracker), then every remaining wall between two corridor cells opened with
// probability `loops`. Loops matter: in a perfect maze every cell off the solution lies in a dead
// end, which dead-end filling removes before the first ant starts.
aco::OccupancyGrid maze_map(int size, int corridor, double loops, aco::Rng& rng, const std::string& name);

// Caves in the style of game maps (Moving AI's dao and bg sets): large open caverns joined by a
// few narrow tunnels. A cellular automaton on a grid `scale` times coarser than the map (each cell
// blocked with probability 0.5, the border blocked, then five rounds of "blocked iff at least 5
// of the 3x3 block are") leaves separate caverns; they are upsampled and smoothed twice by the
// same rule on the map itself, which rounds the scale-cell staircases. Caverns of fewer than
// `scale` x `scale` x 8 cells are filled; the others are joined by a minimum spanning tree of
// straight tunnels 2 to 4 cells wide between their nearest cells, plus the next shortest
// tunnel with probability `loops` per cavern, so there are few ways from one cavern to another.
aco::OccupancyGrid cave_map(int size, int scale, double loops, aco::Rng& rng, const std::string& name);

// Large rooms with few doors, as in the buildings of game maps: the map split recursively (binary
// space partition, across its longer side) by one-cell walls until a room is less than 2 x
// `room` + 1 cells a side, so rooms have `room` to 2 x `room` cells a side. Each wall gets one door
// of 1 to `max_door` cells (so the rooms form a tree: one way from room to room) and, with
// probability `loops`, a second one. A wall never ends in front of an earlier wall's door.
aco::OccupancyGrid hall_map(int size, int room, double loops, int max_door, aco::Rng& rng, const std::string& name);

// An office floor: corridors 2 to 4 cells wide cross the floor three times each way (about every
// quarter of it, jittered), and each block between them is divided as hall_map divides a map into
// offices of `room` to 2 x `room` cells a side, inner doors of 1 to 4 cells. An office on the
// block's edge opens onto the corridor with probability 1/2 through a door of 1 to 4 cells (each
// block through at least one), so there are many ways through a floor, of similar lengths: along
// the corridors, or through suites of offices.
aco::OccupancyGrid office_map(int size, int room, double loops, aco::Rng& rng, const std::string& name);

}  // namespace mapgen
