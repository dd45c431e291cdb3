#!/bin/sh
# Test: the launcher runs the package's interpreter whatever python3 comes first on PATH,
# and the add-on it installs enables in Blender (BLENDER_USER_SCRIPTS: a folder of the
# test's, not the user's). Arguments: <build>/boreas-python, blender, an output folder.
set -eu
launcher=$1 blender=$2 out=$3/launcher
rm -rf "$out"; mkdir -p "$out/bin" "$out/scripts"
printf '#!/bin/sh\necho "the wrong python3 ran" >&2\nexit 3\n' > "$out/bin/python3"
chmod +x "$out/bin/python3"
PATH="$out/bin:$PATH"
export PATH
python3 -c pass 2>/dev/null && { echo "FAIL: the decoy python3 is not first"; exit 1; }
"$launcher" -c "import boreas, numpy; print('ok: boreas', boreas.__version__, 'from', boreas.__file__)"
"$launcher" -m boreas.blender install --addons "$out/scripts/addons"
BLENDER_USER_SCRIPTS="$out/scripts" "$blender" -b --factory-startup --addons boreas_wind \
  --python-exit-code 1 --python-expr \
  "import bpy; assert hasattr(bpy.types, 'BOREAS_PT_panel'), 'add-on not enabled'; print('ok: add-on enabled by --addons')"
