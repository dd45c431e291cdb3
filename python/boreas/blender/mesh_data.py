"""Blender meshes from NumPy arrays in one pass (foreach_set), for the tree's branches and
leaves and the meadow's strips."""
import bpy
import numpy as np


def new_mesh(name, points, triangles, material_index=None):
    """A mesh of triangles: points (V, 3) in Blender's axes, triangles (T, 3) indices,
    material_index (T,) or None."""
    points = np.ascontiguousarray(points, dtype=np.float32).reshape(-1, 3)
    triangles = np.ascontiguousarray(triangles, dtype=np.int32).reshape(-1, 3)
    mesh = bpy.data.meshes.new(name)
    mesh.vertices.add(len(points))
    mesh.vertices.foreach_set("co", points.ravel())
    mesh.loops.add(triangles.size)
    mesh.loops.foreach_set("vertex_index", triangles.ravel())
    mesh.polygons.add(len(triangles))
    mesh.polygons.foreach_set("loop_start", np.arange(0, triangles.size, 3, dtype=np.int32))
    mesh.polygons.foreach_set("loop_total", np.full(len(triangles), 3, np.int32))
    if material_index is not None:
        mesh.polygons.foreach_set("material_index", np.asarray(material_index, np.int32))
    mesh.update(calc_edges=True)
    return mesh


def leaf_geometry(leaves):
    """Each leaf as a diamond of 4 points (base, two sides at mid-length, tip) and 2
    triangles, in boreas's axes: points (4L, 3), triangles (2L, 3)."""
    base = leaves["position"].astype(np.float64)
    axis = leaves["axis"].astype(np.float64)
    side = np.cross(leaves["normal"].astype(np.float64), axis)
    length = leaves["length"].astype(np.float64)[:, None]
    half_width = leaves["width"].astype(np.float64)[:, None] / 2
    mid = base + axis * length / 2
    points = np.stack([base, mid + side * half_width, base + axis * length,
                       mid - side * half_width], axis=1).reshape(-1, 3)
    first = 4 * np.arange(len(leaves))[:, None]
    triangles = np.concatenate([first + [0, 1, 2], first + [0, 2, 3]], axis=1).reshape(-1, 3)
    return points, triangles


def strip_layout(strip_counts, stride):
    """The meadow's strips as one mesh: rows of `stride` vertices, row i drawing its first
    strip_counts[i] as a triangle strip. Returns keep (N,), the drawn vertices' indices into
    the flattened rows, and triangles (T, 3) over the kept vertices, each strip's winding
    kept."""
    keep, triangles, first = [], [], 0
    for row, count in enumerate(np.asarray(strip_counts, dtype=np.int64)):
        keep.extend(range(row * stride, row * stride + count))
        for k in range(count - 2):
            a, b, c = first + k, first + k + 1, first + k + 2
            triangles.append((a, b, c) if k % 2 == 0 else (b, a, c))
        first += count
    return np.array(keep, np.int64), np.array(triangles, np.int32).reshape(-1, 3)
