# The layers above core's stages, checked at configure time like the stages themselves
# (core/CMakeLists.txt): a source that includes a header of a layer it may not use stops the
# configuration with the file and the line.
#
#   core/    only core/ (its stages order themselves: core/CMakeLists.txt)
#   lpy/     core/ and lpy/: L-Py models sit below the program, so nothing of app/
#   app/     core/, lpy/ and app/: the program; nothing of python/
#   python/  core/, lpy/ and app/'s libraries, but not the program's own parts (app/cli/, app/viewer/)
#
# Usage: sprout_check_layer(FOLDER ALLOWED prefix... [FORBIDDEN prefix...])
function(sprout_check_layer folder)
  cmake_parse_arguments(L "" "" "ALLOWED;FORBIDDEN" ${ARGN})
  file(GLOB_RECURSE files CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${folder}/*.cpp ${PROJECT_SOURCE_DIR}/${folder}/*.hpp
       ${PROJECT_SOURCE_DIR}/${folder}/*.c ${PROJECT_SOURCE_DIR}/${folder}/*.h)
  string(REPLACE ";" ", " allowedText "${L_ALLOWED}")
  if(L_FORBIDDEN)
    string(REPLACE ";" ", " forbiddenText "${L_FORBIDDEN}")
    string(APPEND allowedText " but not ${forbiddenText}")
  endif()
  foreach(file ${files})
    file(STRINGS ${file} includes REGEX "^#include \"(core|lpy|app|python)/")
    foreach(line ${includes})
      string(REGEX REPLACE "^#include \"([^\"]+)\".*" "\\1" header "${line}")
      # The prefixes are plain folder names ("app/cli/"), so they join into one regex.
      list(JOIN L_ALLOWED "|" allowed)
      string(REGEX MATCH "^(${allowed})" ok "${header}")
      if(L_FORBIDDEN)
        list(JOIN L_FORBIDDEN "|" forbidden)
        string(REGEX MATCH "^(${forbidden})" refused "${header}")
        if(refused)
          set(ok "")
        endif()
      endif()
      if(NOT ok)
        file(RELATIVE_PATH rel ${PROJECT_SOURCE_DIR} ${file})
        message(FATAL_ERROR "${rel}: '${line}' reaches outside what ${folder}/ may use: ${folder}/ includes only "
                            "${allowedText} (cmake/SproutLayers.cmake, docs/architecture.md)")
      endif()
    endforeach()
  endforeach()
endfunction()

sprout_check_layer(core ALLOWED core/)
sprout_check_layer(lpy ALLOWED core/ lpy/)
sprout_check_layer(app ALLOWED core/ lpy/ app/)
sprout_check_layer(python ALLOWED core/ lpy/ app/ FORBIDDEN app/cli/ app/viewer/)
