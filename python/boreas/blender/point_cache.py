"""The PC2 files meadow bakes write, kept in step with Blender's undo. Undoing a bake takes
its Mesh Cache modifier away but not the file it wrote, which was left in the cache folder
for nothing to read. So after an undo, each file this session's bakes wrote that no Mesh
Cache modifier reads any more is set aside (renamed FILE.undone, beside it); after a redo,
each set-aside file that a modifier reads again is put back; set-aside files are deleted
when Blender loads another .blend or quits. Files the add-on did not write, and files a
modifier still reads, are never touched."""
import atexit
import os

import bpy
from bpy.app.handlers import persistent

ASIDE = ".undone"  # the suffix of a set-aside file

_written = set()  # absolute paths of the files this session's bakes wrote


def _absolute(path):
    return os.path.normpath(bpy.path.abspath(path))


def note_written(path):
    """Remembers a PC2 file a bake wrote (meadow_motion.apply_point_cache)."""
    _written.add(_absolute(path))


def _read():
    """The files the scene's Mesh Cache modifiers read now."""
    return {_absolute(m.filepath) for obj in bpy.data.objects for m in obj.modifiers
            if m.type == "MESH_CACHE"}


@persistent
def after_undo(*_):
    read = _read()
    for path in _written:
        if path not in read and os.path.exists(path):
            os.replace(path, path + ASIDE)


@persistent
def after_redo(*_):
    read = _read()
    for path in _written:
        if path in read and os.path.exists(path + ASIDE):
            os.replace(path + ASIDE, path)


@persistent
def discard(*_):
    """Deletes the set-aside files (no undo reaches them once another .blend is loaded)."""
    for path in _written:
        if os.path.exists(path + ASIDE):
            os.remove(path + ASIDE)
    _written.clear()


_handlers = ((bpy.app.handlers.undo_post, after_undo), (bpy.app.handlers.redo_post, after_redo),
             (bpy.app.handlers.load_pre, discard))


def register():
    for handlers, handler in _handlers:
        if handler not in handlers:
            handlers.append(handler)
    atexit.register(discard)


def unregister():
    for handlers, handler in _handlers:
        if handler in handlers:
            handlers.remove(handler)
    atexit.unregister(discard)
