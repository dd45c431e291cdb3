"""The C library itself through ctypes, for the tests' round trips: the same calls the
extension makes, made directly on the libboreas.so the tests run against (its path in the
BOREAS_LIBRARY environment variable; ctest sets it).

Only the structs the tests need are mirrored; each starts from the library's own
boreas_default_*() value.
"""
import ctypes
import os

import numpy as np
import pytest

c_float3 = ctypes.c_float * 3


class GridDef(ctypes.Structure):
    _fields_ = [("origin", c_float3), ("cell_size", ctypes.c_float),
                ("resolution", ctypes.c_int * 3), ("diffusion", ctypes.c_float),
                ("decay_rate", ctypes.c_float), ("response_time", ctypes.c_float),
                ("edge_fade", ctypes.c_float), ("follow_focus", ctypes.c_int),
                ("wind_sampling", ctypes.c_int)]  # enum boreas_wind_sampling


class Wave(ctypes.Structure):
    _fields_ = [("direction", ctypes.c_float * 2), ("amplitude", ctypes.c_float),
                ("wavelength", ctypes.c_float), ("speed", ctypes.c_float),
                ("sharpness", ctypes.c_float)]


class WorldDef(ctypes.Structure):
    _fields_ = [("device", ctypes.c_char_p), ("cache_dir", ctypes.c_char_p),
                ("grid", GridDef), ("waves", ctypes.POINTER(Wave)),
                ("wave_count", ctypes.c_int),
                ("cl_context_properties", ctypes.POINTER(ctypes.c_ssize_t))]


class Gust(ctypes.Structure):
    _fields_ = [("direction", c_float3), ("strength", ctypes.c_float),
                ("delay", ctypes.c_float), ("rise", ctypes.c_float), ("hold", ctypes.c_float),
                ("fall", ctypes.c_float), ("center", c_float3), ("radius", ctypes.c_float)]


class TreeLevelDef(ctypes.Structure):
    _fields_ = [("stiffness", ctypes.c_float), ("damping_ratio", ctypes.c_float),
                ("frequency_scale", ctypes.c_float), ("rings", ctypes.c_int),
                ("sides", ctypes.c_int)]


class TreeDef(ctypes.Structure):
    _fields_ = [("species", ctypes.c_char_p), ("position", c_float3),
                ("rotation", ctypes.c_float), ("scale", ctypes.c_float),
                ("seed", ctypes.c_uint64), ("mode", ctypes.c_int), ("response", ctypes.c_int),
                ("load", ctypes.c_int), ("bend_exponent", ctypes.c_float),
                ("levels", TreeLevelDef * 4), ("lod_distances", c_float3)]


class Id(ctypes.Structure):
    _fields_ = [("index", ctypes.c_uint32), ("generation", ctypes.c_uint32),
                ("tag", ctypes.c_uint32)]


class CApi:
    """The C functions the tests call, with their signatures."""

    def __init__(self, path):
        lib = ctypes.CDLL(path)
        self.lib = lib
        self.path = path
        sigs = {
            "boreas_last_error": (ctypes.c_char_p, []),
            "boreas_status_name": (ctypes.c_char_p, [ctypes.c_int]),
            "boreas_version": (ctypes.c_char_p, []),
            "boreas_builtin_species": (ctypes.c_char_p, [ctypes.c_int]),
            "boreas_builtin_underbrush_species": (ctypes.c_char_p, [ctypes.c_int]),
            "boreas_default_grid_def": (GridDef, []),
            "boreas_default_wave": (Wave, []),
            "boreas_default_world_def": (WorldDef, []),
            "boreas_default_gust_def": (Gust, []),
            "boreas_default_tree_def": (TreeDef, []),
            "boreas_world_create": (ctypes.c_int, [ctypes.POINTER(WorldDef),
                                                   ctypes.POINTER(ctypes.c_void_p)]),
            "boreas_world_destroy": (None, [ctypes.c_void_p]),
            "boreas_world_step": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_float]),
            "boreas_world_get_state_hash": (ctypes.c_int, [ctypes.c_void_p,
                                                       ctypes.POINTER(ctypes.c_uint64)]),
            "boreas_wind_sample": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_void_p,
                                                  ctypes.c_int, ctypes.c_void_p]),
            "boreas_wind_add_gust": (ctypes.c_int, [ctypes.c_void_p, ctypes.POINTER(Gust),
                                                    ctypes.POINTER(Id)]),
            "boreas_world_add_tree": (ctypes.c_int, [ctypes.c_void_p, ctypes.POINTER(TreeDef),
                                                     ctypes.POINTER(Id)]),
            "boreas_tree_get_branches": (ctypes.c_int, [ctypes.c_void_p, Id, ctypes.c_void_p,
                                                        ctypes.c_int,
                                                        ctypes.POINTER(ctypes.c_int)]),
        }
        for name, (restype, argtypes) in sigs.items():
            fn = getattr(lib, name)
            fn.restype = restype
            fn.argtypes = argtypes
            setattr(self, name[len("boreas_"):], fn)

    def check(self, status):
        assert status == 0, self.last_error().decode()

    def names(self, fn):
        out, i = [], 0
        while (name := fn(i)) is not None:
            out.append(name.decode())
            i += 1
        return out


class CWorld:
    """A world made through the C API directly, from a grid dict and wave dicts."""

    def __init__(self, api, grid, waves):
        self.api = api
        d = api.default_world_def()
        for key, value in grid.items():
            field = getattr(d.grid, key)
            if isinstance(field, ctypes.Array):
                field[:] = value
            else:
                setattr(d.grid, key, value)
        self._waves = (Wave * len(waves))()
        for i, wave in enumerate(waves):
            self._waves[i] = api.default_wave()
            for key, value in wave.items():
                if key == "direction":
                    self._waves[i].direction[:] = value
                else:
                    setattr(self._waves[i], key, value)
        d.waves = self._waves
        d.wave_count = len(waves)
        self.handle = ctypes.c_void_p()
        api.check(api.world_create(ctypes.byref(d), ctypes.byref(self.handle)))

    def close(self):
        if self.handle:
            self.api.world_destroy(self.handle)
            self.handle = ctypes.c_void_p()

    def step(self, dt):
        self.api.check(self.api.world_step(self.handle, dt))

    def sample(self, points):
        points = np.ascontiguousarray(points, dtype=np.float32)
        out = np.empty_like(points)
        self.api.check(self.api.wind_sample(self.handle, points.ctypes.data, len(points),
                                            out.ctypes.data))
        return out

    def state_hash(self):
        h = ctypes.c_uint64()
        self.api.check(self.api.world_get_state_hash(self.handle, ctypes.byref(h)))
        return h.value

    def add_gust(self, **fields):
        g = self.api.default_gust_def()
        for key, value in fields.items():
            field = getattr(g, key)
            if isinstance(field, ctypes.Array):
                field[:] = value
            else:
                setattr(g, key, value)
        self.api.check(self.api.wind_add_gust(self.handle, ctypes.byref(g), None))

    def add_tree(self, species, position, mode=0):
        t = self.api.default_tree_def()
        t.species = species.encode()
        t.position[:] = position
        t.mode = mode
        tree_id = Id()
        self.api.check(self.api.world_add_tree(self.handle, ctypes.byref(t),
                                               ctypes.byref(tree_id)))
        return tree_id

    def branches(self, tree_id, dtype):
        """The tree's branches as raw bytes viewed with the package's dtype."""
        n = ctypes.c_int()
        self.api.check(self.api.tree_get_branches(self.handle, tree_id, None, 0,
                                                  ctypes.byref(n)))
        out = np.zeros(n.value, dtype=dtype)
        self.api.check(self.api.tree_get_branches(self.handle, tree_id, out.ctypes.data,
                                                  n.value, ctypes.byref(n)))
        return out


def load():
    """The C API of the library under test; skips when BOREAS_LIBRARY is not set."""
    path = os.environ.get("BOREAS_LIBRARY")
    if not path:
        pytest.skip("BOREAS_LIBRARY (the libboreas.so under test) is not set; ctest sets it")
    return CApi(path)
