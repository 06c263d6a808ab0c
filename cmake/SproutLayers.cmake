# The layers above core's stages, checked at configure time like the stages themselves
# (core/CMakeLists.txt): a source that includes a header of a layer it may not use stops the
# configuration with the file and the line. docs/architecture.md draws them.
#
#   core/    only core/, its six stages in order: base, language, turtle, environment,
#            derive, scene, each using only those before it; core/language/vlab/ (VLab's
#            object files) only core/base/, the Diagnostic and itself
#   lpy/     core/ and lpy/, its folders in this order, each using only those before it:
#              translate and plantgl (side by side), engine, draw, interpreter, api, run
#              (which defines lpy.hpp). lpy.hpp, its public face, includes core/ and
#              engine/run_options.hpp. Its Python imports nothing of `sprout` (above it).
#   app/     core/, lpy/'s public face and app/: the program; nothing of python/. Its
#            libraries (mesh/ and export/ with no GL, render/, plant/: the one way from a
#            source to a plant, and app/'s own files) below its front ends, cli/ and viewer/,
#            which include nothing of each other; viewer/state/ (no window) below
#            viewer/window/.
#   python/  core/, lpy/'s public face and app/'s libraries, not the program's own parts
#            (app/cli/, app/viewer/)
#
# Also run as a script (cmake -DSPROUT_ROOT=DIR -P cmake/SproutLayers.cmake): the test
# tests/layers/ runs it over the tree, and over trees with a wrong include, which must fail.

# core/'s stages, in order (core/CMakeLists.txt builds them, packaging/ installs them).
set(SPROUT_STAGES base language turtle environment derive scene)

# Usage: sprout_check_layer(FOLDER [FILES glob...] [EXCEPT name...] ALLOWED prefix... [FORBIDDEN prefix...])
# FILES: globs under FOLDER (default: every C/C++ source under it, recursively); EXCEPT: files
# of FOLDER left to a check of their own.
function(sprout_check_layer folder)
  cmake_parse_arguments(L "" "" "FILES;EXCEPT;ALLOWED;FORBIDDEN" ${ARGN})
  set(root ${SPROUT_ROOT})
  if(NOT L_FILES)
    set(L_FILES **.cpp **.hpp **.c **.h)
  endif()
  set(globs "")
  foreach(g ${L_FILES})
    if(g MATCHES "^\\*\\*")
      string(SUBSTRING "${g}" 2 -1 tail)
      list(APPEND recursive ${root}/${folder}/*${tail})
    else()
      list(APPEND globs ${root}/${folder}/${g})
    endif()
  endforeach()
  set(files "")
  if(recursive)
    file(GLOB_RECURSE found ${SPROUT_GLOB_DEPENDS} ${recursive})
    list(APPEND files ${found})
  endif()
  if(globs)
    file(GLOB found ${SPROUT_GLOB_DEPENDS} ${globs})
    list(APPEND files ${found})
  endif()
  foreach(name ${L_EXCEPT})
    list(REMOVE_ITEM files ${root}/${folder}/${name})
  endforeach()
  string(REPLACE ";" ", " allowedText "${L_ALLOWED}")
  if(L_FORBIDDEN)
    string(REPLACE ";" ", " forbiddenText "${L_FORBIDDEN}")
    string(APPEND allowedText " but not ${forbiddenText}")
  endif()
  # The prefixes are plain paths ("app/cli/", "lpy/lpy.hpp"), so they join into one regex.
  list(JOIN L_ALLOWED "|" allowed)
  list(JOIN L_FORBIDDEN "|" forbidden)
  foreach(file ${files})
    file(STRINGS ${file} includes REGEX "^#include \"(core|lpy|app|python)/")
    foreach(line ${includes})
      string(REGEX REPLACE "^#include \"([^\"]+)\".*" "\\1" header "${line}")
      string(REGEX MATCH "^(${allowed})" ok "${header}")
      if(L_FORBIDDEN)
        string(REGEX MATCH "^(${forbidden})" refused "${header}")
        if(refused)
          set(ok "")
        endif()
      endif()
      if(NOT ok)
        file(RELATIVE_PATH rel ${root} ${file})
        message(FATAL_ERROR "${rel}: '${line}' reaches outside what ${folder}/ may use: ${folder}/ includes only "
                            "${allowedText} (cmake/SproutLayers.cmake, docs/architecture.md)")
      endif()
    endforeach()
  endforeach()
endfunction()

# lpy/'s Python is installed as openalea.lpy and openalea.plantgl, below the `sprout` module:
# it imports nothing of it (what it needs of it is handed down: lpy/api/api.hpp).
function(sprout_check_python_imports folder)
  file(GLOB_RECURSE files ${SPROUT_GLOB_DEPENDS} ${SPROUT_ROOT}/${folder}/*.py)
  foreach(file ${files})
    file(STRINGS ${file} imports REGEX "^[ \t]*(import[ \t]+sprout|from[ \t]+sprout)([ \t.,]|$)")
    if(imports)
      list(GET imports 0 line)
      string(STRIP "${line}" line)
      file(RELATIVE_PATH rel ${SPROUT_ROOT} ${file})
      message(FATAL_ERROR "${rel}: '${line}': ${folder}/'s Python is below the sprout module and imports nothing of it "
                          "(cmake/SproutLayers.cmake, docs/architecture.md)")
    endif()
  endforeach()
endfunction()

function(sprout_check_layers)
  # core/'s stages (core/CMakeLists.txt links them in the same order), each allowed those below.
  set(below "")
  foreach(stage ${SPROUT_STAGES})
    list(APPEND below core/${stage}/)
    sprout_check_layer(core/${stage} ALLOWED ${below})
  endforeach()
  # VLab's files: read by the language, below it (core/base and the Diagnostic only).
  sprout_check_layer(core/language/vlab ALLOWED core/base/ core/language/vlab/ core/language/diagnostic.hpp)
  sprout_check_layer(core ALLOWED core/)
  # lpy/, folder by folder, each allowed the ones before it.
  set(below core/)
  foreach(sub translate plantgl engine draw interpreter api run)
    list(APPEND below lpy/${sub}/)
    set(allowed ${below})
    if(sub STREQUAL "plantgl")
      set(allowed core/ lpy/plantgl/)  # beside translate/, not above it
    elseif(sub STREQUAL "run")
      list(APPEND allowed lpy/lpy.hpp)  # what it defines
    endif()
    sprout_check_layer(lpy/${sub} ALLOWED ${allowed})
  endforeach()
  sprout_check_layer(lpy FILES *.hpp *.cpp ALLOWED core/ lpy/engine/run_options.hpp)
  sprout_check_python_imports(lpy)
  # app/: its libraries below its two front ends, which include nothing of each other.
  set(app_top "app/[a-z_]+[.]hpp")  # app/'s own files: headless pictures, snapshots, arguments...
  sprout_check_layer(app/mesh ALLOWED core/ app/mesh/)
  sprout_check_layer(app/render ALLOWED core/ app/mesh/ app/render/)
  sprout_check_layer(app/export ALLOWED core/ app/mesh/ app/export/)
  sprout_check_layer(app/plant ALLOWED core/ lpy/lpy.hpp app/plant/)
  set(app_libraries core/ lpy/lpy.hpp app/mesh/ app/render/ app/export/ app/plant/ ${app_top})
  sprout_check_layer(app FILES *.hpp *.cpp EXCEPT main.cpp ALLOWED ${app_libraries})
  sprout_check_layer(app/cli ALLOWED ${app_libraries} app/cli/)
  sprout_check_layer(app/viewer/state ALLOWED core/ lpy/lpy.hpp app/plant/ app/viewer/state/)
  sprout_check_layer(app/viewer/window ALLOWED ${app_libraries} app/viewer/)
  sprout_check_layer(app FILES main.cpp ALLOWED ${app_libraries} app/cli/commands.hpp app/viewer/window/viewer.hpp)
  sprout_check_layer(python ALLOWED core/ lpy/lpy.hpp app/ FORBIDDEN app/cli/ app/viewer/)
endfunction()

if(CMAKE_SCRIPT_MODE_FILE)
  set(SPROUT_GLOB_DEPENDS "")
  if(NOT SPROUT_ROOT)
    message(FATAL_ERROR "usage: cmake -DSPROUT_ROOT=DIR -P cmake/SproutLayers.cmake")
  endif()
  sprout_check_layers()
else()
  set(SPROUT_ROOT ${PROJECT_SOURCE_DIR})
  set(SPROUT_GLOB_DEPENDS CONFIGURE_DEPENDS)  # a file added or moved is checked at the next build
  sprout_check_layers()
endif()
