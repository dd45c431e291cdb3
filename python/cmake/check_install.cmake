# boreas for Python: the installed package works. Installs the build into a temporary
# prefix (cmake -P; BUILD_DIR, PREFIX, PACKAGE_DIR relative to it, PYTHON), then imports
# boreas from there in a fresh interpreter, with nothing of the build tree on its path, and
# samples a world's wind.
file(REMOVE_RECURSE "${PREFIX}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${PREFIX}"
  OUTPUT_QUIET RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${rc})")
endif()
set(package "${PREFIX}/${PACKAGE_DIR}/boreas")
foreach(file __init__.py __init__.pyi _boreas.pyi py.typed blender/__init__.py blender/bake.py)
  if(NOT EXISTS "${package}/${file}")
    message(FATAL_ERROR "not installed: ${package}/${file}")
  endif()
endforeach()
set(ENV{PYTHONPATH} "${PREFIX}/${PACKAGE_DIR}")
execute_process(COMMAND "${PYTHON}" -c [=[
import sys, boreas
assert boreas.__file__.startswith(sys.argv[1]), boreas.__file__
with boreas.World(grid={"resolution": (4, 2, 4)}, waves=[{"amplitude": 2.0, "sharpness": 0}]) as w:
    wind = w.wind.sample([[0.0, 1.0, 0.0]])
    assert abs(wind[0, 0] - 2.0) < 1e-5, wind
print("installed boreas", boreas.__version__, "from", boreas.__file__)
]=] "${package}" WORKING_DIRECTORY "${PREFIX}" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the installed package did not import and run (${rc})")
endif()
