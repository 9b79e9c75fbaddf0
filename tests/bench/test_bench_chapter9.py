"""bench/bench_chapter9's scripted teleop tour on a small synthetic maze: the cell graph read
from a grid, a seeded depth-first tour over every reachable cell, and its waypoints."""

import math
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench_script import load_bench_script  # noqa: E402

bench = load_bench_script("bench_chapter9")

RES = 0.1
CELL = 1.0  # 10 grid cells per maze cell


def grid_3x3():
    """A 3 x 3 maze of 1 m cells with walls one grid cell thick:

    +---+---+---+
    |       |   |
    +   +---+   +
    |   |       |
    +   +   +---+      (2, 0) is walled off from everything
    |       |   |
    +---+---+---+
    """
    cells = np.zeros((30, 30), dtype=np.int8)
    cells[0, :] = cells[-1, :] = cells[:, 0] = cells[:, -1] = 100
    cells[0:10, 20] = 100  # between (1, 0) and (2, 0)
    cells[10, 20:30] = 100  # between (2, 0) and (2, 1)
    cells[10:20, 10] = 100  # between (0, 1) and (1, 1)
    cells[20, 10:20] = 100  # between (1, 1) and (1, 2)
    cells[20:30, 20] = 100  # between (1, 2) and (2, 2)
    return cells, RES, (0.0, 0.0, 0.0)


def test_cell_graph_joins_cells_without_a_wall_between():
    graph = bench.cell_graph(grid_3x3(), CELL)
    assert len(graph) == 9
    assert graph[(2, 0)] == []
    assert sorted(graph[(1, 1)]) == [(1, 0), (2, 1)]
    assert sorted(graph[(0, 1)]) == [(0, 0), (0, 2)]
    assert (1, 2) in graph[(0, 2)] and (2, 2) not in graph[(1, 2)]


def test_tour_visits_every_reachable_cell_along_open_edges():
    graph = bench.cell_graph(grid_3x3(), CELL)
    for seed in range(5):
        path = bench.maze_tour(graph, (0, 0), seed)
        assert path[0] == (0, 0)
        assert set(path) == set(graph) - {(2, 0)}
        assert all(b in graph[a] for a, b in zip(path, path[1:], strict=False))
        assert path.count(path[-1]) == 1  # it ends on the last new cell
    assert bench.maze_tour(graph, (0, 0), 1) == bench.maze_tour(graph, (0, 0), 1)


def test_waypoints_are_the_turns_and_the_end():
    path = [(0, 0), (0, 1), (0, 2), (1, 2), (2, 2), (2, 1)]
    points = bench.tour_waypoints(path, CELL)
    assert points == [[0.5, 2.5], [2.5, 2.5], [2.5, 1.5]]
    assert math.isclose(bench.path_length(points, (0.5, 0.5)), 5.0)
