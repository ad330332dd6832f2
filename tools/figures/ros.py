"""docs/ros.md's figures: a plan aco-ros-planner served, drawn, and the node's speed on a 512x512
map, from a ROS session of the section's own (tools/ros/ros_session.py)."""
from __future__ import annotations

import math
import statistics
import sys
import tempfile
import time
from pathlib import Path

from .formatting import table
from .project import BUILD, IMAGES, ROOT, ROS
from .run import Run
from .sections import section

sys.path.insert(0, str(ROOT / "tools/ros"))
from publish_map import occupancy_grid  # noqa: E402
from ros_session import NODE, RosSession, cell_centre  # noqa: E402

OFFICE = Path("data/maps/ros/office.yaml")
OFFICE_CELLS = ((8, 8), (90, 60))  # aco's cells (x, row from the top): docs/ros.md's rosservice call
CITY = Path("data/maps/movingai/street/Berlin_0_512.map")
CITY_RESOLUTION, CITY_ORIGIN = 0.05, (-12.8, -3.2)  # metres: a 25.6 m square off the frame's origin
REQUESTS = 20  # the city's scenarios, spread over its file's second half (the longer ones)
COLONIES = [("robust (the default)", {}), ("a small colony: `~ants 10 ~iterations 20`", {"ants": 10, "iterations": 20})]


def moving_ai_grid(map_file: Path):
    """A Moving AI .map as a nav_msgs/OccupancyGrid: '.', 'G' and 'S' free (0), the rest occupied."""
    from nav_msgs.msg import OccupancyGrid
    lines = (ROOT / map_file).read_text().splitlines()
    height, width = int(lines[1].split()[1]), int(lines[2].split()[1])
    rows = lines[4:4 + height]
    grid = OccupancyGrid()
    grid.header.frame_id = "map"
    grid.info.resolution, grid.info.width, grid.info.height = CITY_RESOLUTION, width, height
    grid.info.origin.position.x, grid.info.origin.position.y = CITY_ORIGIN
    grid.info.origin.orientation.w = 1.0
    grid.data = [0 if rows[height - 1 - r][x] in ".GS" else 100 for r in range(height) for x in range(width)]
    return grid


def svg(grid, points) -> str:
    """The map (free white, occupied dark, unknown grey) and the plan, 6 px per cell, north up."""
    info, scale = grid.info, 6
    w, h = info.width, info.height
    colour = {100: "#333", -1: "#bbb"}
    parts = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{w * scale}" height="{h * scale}" '
             f'viewBox="0 0 {w} {h}"><rect width="{w}" height="{h}" fill="#fff"/>']
    for row in range(h):  # runs of one kind per row, the grid's first row at the bottom
        y, x = h - 1 - row, 0
        while x < w:
            value = grid.data[row * w + x]
            end = x
            while end < w and grid.data[row * w + end] == value:
                end += 1
            if value in colour:
                parts.append(f'<rect x="{x}" y="{y}" width="{end - x}" height="1" fill="{colour[value]}"/>')
            x = end
    cells = [((px - info.origin.position.x) / info.resolution, h - (py - info.origin.position.y) / info.resolution)
             for px, py in points]
    parts.append('<polyline fill="none" stroke="#1f6fd1" stroke-width="0.6" stroke-linejoin="round" points="'
                 + " ".join(f"{x:.3f},{y:.3f}" for x, y in cells) + '"/>')
    for (x, y), fill in ((cells[0], "#2a9d3a"), (cells[-1], "#d1342f")):
        parts.append(f'<circle cx="{x:.3f}" cy="{y:.3f}" r="1.2" fill="{fill}"/>')
    return "".join(parts) + "</svg>\n"


def scenarios(map_file: Path):
    """(start, goal, optimal length in cells) of the .scen's second half, REQUESTS of them spread over it."""
    lines = [line.split() for line in (ROOT / map_file).with_suffix(".map.scen").read_text().splitlines()[1:] if line]
    half = lines[len(lines) // 2:]
    picked = [half[i * len(half) // REQUESTS] for i in range(REQUESTS)]
    return [((int(s[4]), int(s[5])), (int(s[6]), int(s[7])), float(s[8])) for s in picked]


@section("ros", "1-2 min", "docs/ros.md: a plan aco-ros-planner served (SVG), the node's speed on a 512x512 map",
         [(ROS, "ros-plan"), (ROS, "ros-speed")])
def ros(run: Run):
    import rospy
    run.commands.append("tools/ros/ros_session.py: rosmaster on a free port, build/release/bin/aco-ros-planner, "
                        "maps published and make_plan called with rospy")
    with tempfile.TemporaryDirectory() as scratch, RosSession(Path(scratch), ROOT / BUILD) as ros_session:
        ros_session.start_node({})
        office = occupancy_grid(ROOT / OFFICE, "map")
        ros_session.publish(office, "aco planner: map 100x70")
        start, goal = (cell_centre(office.info, c) for c in OFFICE_CELLS)
        plan, _ = ros_session.make_plan(start, goal)
        points = [(p.pose.position.x, p.pose.position.y) for p in plan.poses]
        (ROOT / IMAGES).mkdir(parents=True, exist_ok=True)
        (ROOT / IMAGES / "ros-plan.svg").write_text(svg(office, points))
        length = sum(math.dist(a, b) for a, b in zip(points, points[1:]))
        served = (run.stamp() + "\n\n![The bundled office map: the plan aco-ros-planner served from the top-left room "
                  "to the bottom-right one, in blue from the green start to the red goal](images/ros-plan.svg)\n\n"
                  f"The plan of the `rosservice call` above, as the node served it: {len(points)} poses, "
                  f"{length:.2f} m, with the node's defaults (the robust preset, a clearance of a quarter cell).")

        city = moving_ai_grid(CITY)
        rows = []
        for label, parameters in COLONIES:
            for key in ("ants", "iterations"):
                if rospy.has_param(f"{NODE}/{key}"):
                    rospy.delete_param(f"{NODE}/{key}")
            for key, value in parameters.items():
                rospy.set_param(f"{NODE}/{key}", value)
            ros_session.publish(city, f"aco planner: map {city.info.width}x{city.info.height}")
            latencies, ratios, solved = [], [], 0
            began = time.perf_counter()
            for start_cell, goal_cell, optimum in scenarios(CITY):
                asked = time.perf_counter()
                plan, _ = ros_session.make_plan(cell_centre(city.info, start_cell), cell_centre(city.info, goal_cell))
                latencies.append(time.perf_counter() - asked)
                if plan.poses:
                    solved += 1
                    pts = [(p.pose.position.x, p.pose.position.y) for p in plan.poses]
                    ratios.append(sum(math.dist(a, b) for a, b in zip(pts, pts[1:])) / city.info.resolution / optimum)
            total = time.perf_counter() - began
            rows.append([label, f"{solved}/{REQUESTS}", f"{REQUESTS / total:.2f}", f"{latencies[0] * 1000:.0f} ms",
                         f"{statistics.median(latencies[1:]) * 1000:.0f} ms",
                         f"{statistics.mean(ratios):.3f}" if ratios else "-", f"{max(ratios):.3f}" if ratios else "-"])
        speed = (run.stamp() + f"\n\n{CITY.name} (512x512) as an occupancy grid of {CITY_RESOLUTION} m cells off the "
                 f"frame's origin, {REQUESTS} of its scenarios (the second half of its `.scen`, the longer ones) "
                 "asked one after the other with rospy, the node's defaults otherwise (all cores). Requests per "
                 "second: the requests over the wall time of all of them, as the client waits; the first request "
                 "comes right after the map (the node builds the graph at every request, so it is not slower than the "
                 "others); final / grid optimum: the served path's length over the scenario's optimal grid length "
                 "(8 moves, no corner cutting):\n\n"
                 + table(["colony", "solved", "requests per second", "first request after the map",
                          "median latency", "final / grid optimum (mean)", "(worst)"], rows))
        left = ros_session.left_running
    if left():
        raise RuntimeError(f"section 'ros' left processes running: {left()}")
    return {(ROS, "ros-plan"): served, (ROS, "ros-speed"): speed}
