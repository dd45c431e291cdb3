"""python3 -m boreas.blender install [--addons DIR]: makes the add-on visible to Blender.

Writes boreas_wind.py into Blender's user add-on folder (default
~/.config/blender/<version>/scripts/addons for each Blender version found there, else
3.4): a small add-on that puts this package's folder on Blender's sys.path (Blender
ignores PYTHONPATH) and registers boreas.blender. Then enable "boreas wind" in Edit >
Preferences > Add-ons, or start Blender with --addons boreas_wind.
"""
import argparse
import glob
import os
import sys

import boreas

from . import bl_info

ADDON = "boreas_wind.py"

TEMPLATE = '''"""boreas wind: the add-on of the boreas package at {package} (written by
python3 -m boreas.blender install)."""
bl_info = {bl_info!r}

import sys
if {root!r} not in sys.path:
    sys.path.append({root!r})


def register():
    import boreas.blender
    boreas.blender.register()


def unregister():
    import boreas.blender
    boreas.blender.unregister()
'''


def default_folders():
    config = os.environ.get("XDG_CONFIG_HOME") or os.path.expanduser("~/.config")
    found = sorted(glob.glob(os.path.join(config, "blender", "*", "")))
    versions = found or [os.path.join(config, "blender", "3.4", "")]
    return [os.path.join(v, "scripts", "addons") for v in versions]


def install(folders):
    package = os.path.dirname(os.path.abspath(boreas.__file__))
    text = TEMPLATE.format(package=package, bl_info=bl_info, root=os.path.dirname(package))
    written = []
    for folder in folders:
        os.makedirs(folder, exist_ok=True)
        path = os.path.join(folder, ADDON)
        with open(path, "w", encoding="utf-8") as f:
            f.write(text)
        written.append(path)
    return written


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python3 -m boreas.blender",
                                     description="Makes the boreas add-on visible to Blender.")
    parser.add_argument("command", choices=["install"])
    parser.add_argument("--addons", action="append",
                        help="the add-on folder to write into (default: Blender's user "
                             "add-on folder of each version under ~/.config/blender)")
    args = parser.parse_args(argv)
    for path in install(args.addons or default_folders()):
        print(f"wrote {path}; enable 'boreas wind' in Blender's Preferences > Add-ons "
              f"or start blender --addons boreas_wind")
    return 0


if __name__ == "__main__":
    sys.exit(main())
