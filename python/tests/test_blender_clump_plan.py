"""The Blender add-on's bpy-free clump plan (boreas.blender.clump_plan) on a meadow made
here: every cell with plants is an instance, of one of n clumps, at its cell's center and
ground height; a clump's own cell has phase 0; shares hold the cells ranked by their
strip vertices; a loop ends where it starts and a phase starts it later; the window of a
swaying point is the one about a turn of its sway."""
import numpy as np
import pytest

from boreas.blender.clump_plan import ClumpPlan, loop_window, looped, phase_of

COMPONENT = np.dtype([("base", "<f4", 3), ("parent", "<i4")])


def meadow():
    """A 4 x 2 m meadow: cell (i, j) of 1 m holds i + 1 grounded blades (none in (3, 1)) at
    ground height 0.1 j, each blade with a leaf on it; 2 strip vertices a component (rows of
    4)."""
    bases, parents = [], []
    for j in range(2):
        for i in range(4):
            if (i, j) == (3, 1):
                continue
            for b in range(i + 1):
                bases.append((i + 0.2 + 0.15 * b, 0.1 * j, j + 0.5))
                parents.append(-1)
                bases.append((i + 0.2 + 0.15 * b, 0.1 * j + 0.3, j + 0.5))
                parents.append(len(bases) - 2)
    c = np.zeros(len(bases), COMPONENT)
    c["base"], c["parent"] = bases, parents
    keep = np.array([4 * r + v for r in range(len(c)) for v in range(2)])
    return c, keep


def test_every_cell_with_plants_is_an_instance_of_its_shares_clump():
    c, keep = meadow()
    plan = ClumpPlan(c, keep, 4, clumps=3, size=1.0, phases=5)
    assert len(plan.instances) == 7  # 8 cells, one empty
    assert len(plan.clumps) == 3 == len(plan.own)
    per_cell = {cell: (k, phase, origin) for k, phase, origin, cell in plan.instances}
    lo_x, lo_z = 0.2, 0.5  # the grounded bases' lowest x and z: the grid's corner
    for cell, (k, phase, origin) in per_cell.items():
        column, row = cell % 4, cell // 4
        assert origin == pytest.approx([lo_x + column + 0.5, 0.1 * row, lo_z + row + 0.5])
        assert (phase == 0) if cell == plan.own[k] else (0 <= phase < 5)
        assert phase == (0 if cell == plan.own[k] else phase_of(cell, 5))
    # Strip vertices a cell: 4 (column + 1). Ranked: cells 0, 4 (4), 1, 5 (8), 2, 6 (12),
    # 3 (16); three shares [0, 4], [1, 5], [2, 6, 3], each's clump its first cell nearest
    # the share's mean (4, 8, 13.3).
    assert plan.own == [0, 1, 2]
    assert {cell: k for cell, (k, _, _) in per_cell.items()} == \
        {0: 0, 4: 0, 1: 1, 5: 1, 2: 2, 6: 2, 3: 2}
    assert [len(v) for v, _ in plan.clumps] == [4, 8, 12]
    assert sorted(np.concatenate([v for v, _ in plan.clumps])) == sorted(plan.vertices)


def test_a_loop_ends_where_it_starts_and_a_phase_starts_it_later():
    rng = np.random.default_rng(1)
    frames = rng.normal(size=(9, 5, 3))
    loop = looped(frames, 0, 4)
    assert np.allclose(loop[-1], loop[0])
    drift = frames[-1] - frames[0]
    for k in range(9):
        assert np.allclose(loop[k], frames[k] - k / 8 * drift)
    later = looped(frames, 1, 4)  # a quarter of 8 frames in
    for k in range(9):
        assert np.allclose(later[k], loop[(k + 2) % 8])


def test_the_window_of_a_sway_lies_about_a_turn():
    t = np.arange(40) * 0.1
    x = np.sin(2 * np.pi * t / 3.0)  # a 3 s sway; windows of 1.1 s (12 frames)
    frames = np.stack([x, np.zeros_like(x), np.zeros_like(x)], axis=1)[:, None, :]
    start = loop_window(frames, 12)
    assert abs(frames[start + 11, 0, 0] - frames[start, 0, 0]) < 1e-9
    turn = (start + 5.5) * 0.1  # the window's middle: the first crest (0.75 s)
    assert turn == pytest.approx(0.75)
