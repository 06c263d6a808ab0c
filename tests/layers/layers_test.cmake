# The configure-time layer check (cmake/SproutLayers.cmake) run as a test: the tree passes, and
# each wrong include (or lpy/ Python importing sprout), put alone into a scratch tree, fails
# with its file named.
#   cmake -DSPROUT_SOURCE=DIR -DSCRATCH=DIR -P tests/layers/layers_test.cmake
set(check ${SPROUT_SOURCE}/cmake/SproutLayers.cmake)
execute_process(COMMAND ${CMAKE_COMMAND} -DSPROUT_ROOT=${SPROUT_SOURCE} -P ${check} RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the tree breaks its own layers:\n${err}")
endif()

# FILE|LINE: a file that may not hold that line.
set(wrong
  "core/turtle/x.cpp|#include \"core/derive/derive.hpp\""
  "core/base/x.cpp|#include \"lpy/lpy.hpp\""
  "lpy/translate/x.cpp|#include \"lpy/engine/engine.hpp\""
  "lpy/plantgl/x.cpp|#include \"lpy/translate/translate.hpp\""
  "lpy/engine/x.hpp|#include \"lpy/lpy.hpp\""
  "lpy/engine/x.cpp|#include \"lpy/draw/draw.hpp\""
  "lpy/draw/x.cpp|#include \"lpy/interpreter/interpreter.hpp\""
  "lpy/interpreter/x.cpp|#include \"lpy/api/api.hpp\""
  "lpy/api/x.cpp|#include \"lpy/run/x.hpp\""
  "lpy/lpy.hpp|#include \"lpy/engine/engine.hpp\""
  "lpy/run/x.cpp|#include \"app/plant/source.hpp\""
  "lpy/api/x.py|import sprout"
  "lpy/plantgl/x.py|    from sprout import _sprout"
  "app/x.cpp|#include \"lpy/engine/engine.hpp\""
  "app/x.cpp|#include \"app/cli/load.hpp\""
  "app/x.cpp|#include \"app/viewer/state/worker.hpp\""
  "app/cli/x.cpp|#include \"app/viewer/window/app.hpp\""
  "app/cli/x.cpp|#include \"app/viewer/state/trust.hpp\""
  "app/viewer/window/x.cpp|#include \"app/cli/load.hpp\""
  "app/viewer/state/x.cpp|#include \"app/viewer/window/app.hpp\""
  "app/viewer/state/x.cpp|#include \"app/render/gl.hpp\""
  "app/export/x.cpp|#include \"app/render/gl.hpp\""
  "app/export/x.cpp|#include \"app/render/renderer.hpp\""
  "app/mesh/x.cpp|#include \"app/render/renderer.hpp\""
  "app/render/x.cpp|#include \"app/export/export.hpp\""
  "app/plant/x.cpp|#include \"app/snapshot.hpp\""
  "app/plant/x.cpp|#include \"lpy/engine/engine.hpp\""
  "app/x.cpp|#include \"python/x.hpp\""
  "python/x.cpp|#include \"app/viewer/state/worker.hpp\""
  "python/x.cpp|#include \"app/cli/load.hpp\"")
set(n 0)
foreach(entry IN LISTS wrong)
  string(REPLACE "|" ";" parts "${entry}")
  list(GET parts 0 file)
  list(GET parts 1 line)
  set(tree ${SCRATCH}/tree${n})
  math(EXPR n "${n} + 1")
  file(REMOVE_RECURSE ${tree})
  file(WRITE ${tree}/${file} "${line}\n")
  execute_process(COMMAND ${CMAKE_COMMAND} -DSPROUT_ROOT=${tree} -P ${check} RESULT_VARIABLE rc ERROR_VARIABLE err)
  string(REPLACE "\n" " " flat "${err}")
  if(rc EQUAL 0 OR NOT flat MATCHES "${file}")
    message(FATAL_ERROR "the layer check let ${file} hold '${line}' (exit ${rc}):\n${err}")
  endif()
endforeach()
message(STATUS "${n} wrong includes refused, each naming its file")
