# Debian's Python (python3-dev) and pybind11 (pybind11-dev), for lpy/ (the embedded interpreter)
# and python/ (the `sprout` module); imported targets belong to the folder that finds them, so
# each includes this. Not another python3 first on PATH: pybind11-dev is built for Debian's.
if(NOT DEFINED Python_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python_EXECUTABLE /usr/bin/python3)
endif()
set(PYBIND11_FINDPYTHON ON)
find_package(Python 3 COMPONENTS Interpreter Development.Embed Development.Module)
find_package(pybind11 CONFIG QUIET)
