"""A meadow as instanced clumps, the plan (no bpy: NumPy on what the bake recorded), as the
animated glTF cuts it (boreas_animation_def.meadow_clumps): the ground under the meadow in
square cells; its cells with plants ranked by their strip vertices in `clumps` equal shares,
a share's clump its cell nearest the share's mean count; every cell of a share an instance
of its clump at the cell's center and ground height. Blender plays a collection instance
without evaluating it again, so each clump is baked at `phases` starts in its loop (the
drift from the first frame to the last taken out, as the glTF's loops) and a cell takes one
of them: the meadow's motion costs clumps x phases meshes a frame, not all of its vertices.
The bake steps on past its last frame (2 (frames - 1) more) for each clump to take the
window of its frames that closes best (loop_window), as the glTF's clumps do.
"""
import numpy as np


def _roots(parent):
    """Each component's root (the one fixed to the ground)."""
    root = np.arange(len(parent))
    for _ in range(len(parent)):
        up = parent[root]
        if (up < 0).all():
            break
        root = np.where(up >= 0, up, root)
    return root


def phase_of(cell, phases):
    """A cell's phase, 0..phases - 1: a hash of its number, so neighbours differ."""
    z = (int(cell) + 0x9E3779B97F4A7C15) & 0xFFFFFFFFFFFFFFFF
    z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & 0xFFFFFFFFFFFFFFFF
    z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & 0xFFFFFFFFFFFFFFFF
    return int((z ^ (z >> 31)) % phases)


class ClumpPlan:
    """components: the meadow's (COMPONENT_DTYPE, boreas's axes); keep: its drawn strip
    vertices' indices in rows of `stride` (mesh_data.strip_layout; row i is component i).

    clumps[k]: (vertices, origin): the clump's indices into the kept vertices and its
    cell's origin (boreas's axes: center x, ground y, center z); own[k]: that cell.
    instances: (k, phase, origin, cell) per cell with plants; a clump's own cell has phase
    0 (so it plays as boreas stepped it, but for the loop's drift)."""

    def __init__(self, components, keep, stride, clumps=4, size=1.0, phases=4):
        if clumps < 1 or phases < 1 or not size > 0:
            raise ValueError(f"clumps ({clumps}) and phases ({phases}) must be at least 1 and "
                             f"the cell size ({size:g} m) positive")
        parent = np.asarray(components["parent"], np.int64)
        base = np.asarray(components["base"], np.float64)
        root = _roots(parent)
        grounded = parent < 0
        lo = base[grounded][:, [0, 2]].min(axis=0)
        cell_xz = np.floor((base[root][:, [0, 2]] - lo) / size).astype(np.int64)
        columns = int(cell_xz[:, 0].max()) + 1
        cell = cell_xz[:, 0] + columns * cell_xz[:, 1]  # per component
        vertex_cell = cell[np.asarray(keep) // stride]
        filled = np.unique(cell[grounded])
        count = np.array([(vertex_cell == c).sum() for c in filled])
        ground = np.array([base[grounded & (cell == c), 1].mean() for c in filled])
        origin = {int(c): np.array([lo[0] + (c % columns + 0.5) * size, g,
                                    lo[1] + (c // columns + 0.5) * size])
                  for c, g in zip(filled, ground)}
        ranked = np.argsort(count, kind="stable")
        n = min(clumps, len(filled))
        self.clumps, self.own, self.instances = [], [], []
        for k in range(n):
            share = ranked[k * len(ranked) // n:(k + 1) * len(ranked) // n]
            own = share[np.argmin(np.abs(count[share] - count[share].mean()))]
            c = int(filled[own])
            self.clumps.append((np.flatnonzero(vertex_cell == c), origin[c]))
            self.own.append(c)
            for i in share:
                other = int(filled[i])
                self.instances.append((k, 0 if other == c else phase_of(other, phases),
                                       origin[other], other))
        self.phases = phases
        # every clump's vertices, clump after clump (what a bake records of the meadow)
        self.vertices = np.concatenate([v for v, _ in self.clumps]) if self.clumps else \
            np.zeros(0, np.int64)


def loop_window(frames, count):
    """frames (K, N, 3), K >= count: the first frame of the window of `count` frames whose
    last frame is nearest its first (the farthest vertex; the earliest of equals), as the
    animated glTF's clumps take theirs: in a sway, a window about a turn of the motion."""
    frames = np.asarray(frames, np.float64)
    seams = [np.linalg.norm(frames[s + count - 1] - frames[s], axis=1).max()
             for s in range(len(frames) - count + 1)]
    return int(np.argmin(seams))


def looped(frames, phase, phases):
    """frames (F, N, 3), a clump's vertices at each baked frame: the drift from the first
    to the last taken out linearly (frame k moves by -k / (F - 1) of it), so the last is the
    first, and the loop started round(phase (F - 1) / phases) frames in."""
    frames = np.asarray(frames, np.float64)
    count = len(frames)
    if count < 2:
        return frames.copy()
    steps = np.arange(count, dtype=np.float64)[:, None, None] / (count - 1)
    loop = frames - steps * (frames[-1] - frames[0])
    start = int(round(phase * (count - 1) / phases))
    return loop[(np.arange(count) + start) % (count - 1)]
