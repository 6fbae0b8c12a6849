# ctest `filters.install`: cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... -DPYTHON=...
# -DGENERATOR=... -P
cmake_minimum_required(VERSION 3.16) # (policies: if() compares quoted strings as strings)
# Installs the build tree into WORK_DIR/prefix, then builds and runs tests/install (a project of a
# user's own that finds the installed Tessera) and imports the installed Python package.
function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${what} failed (${status}):\n${out}\n${err}")
  endif()
  set(output "${out}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
run("cmake --install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
# The installed targets name GeographicLib by name, not by a path of the machine that built them
# (they held /usr/lib/x86_64-linux-gnu/libGeographicLib.so and /usr/include).
file(GLOB_RECURSE core_targets ${prefix}/*TesseraCore-targets*.cmake)
if(NOT core_targets)
  message(FATAL_ERROR "no TesseraCore-targets*.cmake installed under ${prefix}")
endif()
foreach(file IN LISTS core_targets)
  file(READ ${file} text)
  if(text MATCHES "libGeographicLib|/usr/include")
    message(FATAL_ERROR "${file} names a path of this machine: ${CMAKE_MATCH_0}")
  endif()
endforeach()
# Both targets; then the core alone, from a C++-only project that must not need ParaView.
foreach(consumer IN ITEMS consumer core_consumer)
  if(consumer STREQUAL "consumer")
    set(project ${SOURCE_DIR}/tests/install)
  else()
    set(project ${SOURCE_DIR}/tests/install/core_only)
  endif()
  run("configuring ${consumer}" ${CMAKE_COMMAND} -S ${project} -B ${WORK_DIR}/${consumer}
    -G ${GENERATOR} -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${prefix})
  if(output MATCHES "installed without its VTK filters")
    message(FATAL_ERROR "a full install said it has no filters to ${consumer}:\n${output}")
  endif()
  run("building ${consumer}" ${CMAKE_COMMAND} --build ${WORK_DIR}/${consumer})
  # A GoogleTest program: a failed check exits non-zero (run fails); one that ran no test, too.
  run("running ${consumer}" ${WORK_DIR}/${consumer}/${consumer})
  if(NOT output MATCHES "\\[  PASSED  \\] 1 test")
    message(FATAL_ERROR "${consumer} did not pass its one test:\n${output}")
  endif()
endforeach()
# An install made without the VTK filters (TESSERA_BUILD_VTK=OFF) holds the core's files only: a
# project asking it for Tessera::Filters is told so by name (simulated here by a copy of the
# prefix without the filters' CMake files, as a core-only build would install it).
set(core_prefix ${WORK_DIR}/core_only_prefix)
file(COPY ${prefix}/ DESTINATION ${core_prefix})
file(GLOB filters_files ${core_prefix}/lib*/cmake/tessera/Tessera-*.cmake)
if(NOT filters_files)
  message(FATAL_ERROR "no Tessera-*.cmake (the filters' targets) installed under ${prefix}")
endif()
file(REMOVE ${filters_files})
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/install
  -B ${WORK_DIR}/filters_from_core_only -G ${GENERATOR} -DCMAKE_PREFIX_PATH=${core_prefix}
  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(REGEX REPLACE "[ \n]+" " " said "${out} ${err}") # (CMake wraps the message's lines)
if(status EQUAL 0 OR NOT said MATCHES "installed without its VTK filters \\(configured with TESSERA_BUILD_VTK=OFF\\), so it has no Tessera::Filters")
  message(FATAL_ERROR "asking a core-only install for Tessera::Filters (${status}):\n${out}\n${err}")
endif()
# Asked for no component in particular, it says what it lacks before CMake's "target not found".
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/install
  -B ${WORK_DIR}/no_component_from_core_only -G ${GENERATOR} -DCMAKE_PREFIX_PATH=${core_prefix}
  -DASK_NO_COMPONENT=ON RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(REGEX REPLACE "[ \n]+" " " said "${out} ${err}")
if(status EQUAL 0 OR NOT said MATCHES "installed without its VTK filters \\(TESSERA_BUILD_VTK=OFF\\): Tessera::core only, no Tessera::Filters")
  message(FATAL_ERROR "a core-only install found without components (${status}):\n${out}\n${err}")
endif()
# The installed Python package, alone on the path (not the build tree's).
# (A script file: a semicolon in an argument would split it as a CMake list.)
file(WRITE ${WORK_DIR}/import.py "import os\nimport tessera\n"
  "from tessera import vtkDirichletTessellation\n"
  "vtkDirichletTessellation()\nprint(os.path.dirname(tessera.__file__))\n")
run("importing the installed package" ${CMAKE_COMMAND} -E env PYTHONPATH=${prefix}/python
  ${PYTHON} ${WORK_DIR}/import.py)
string(STRIP "${output}" where)
if(NOT where STREQUAL "${prefix}/python/tessera")
  message(FATAL_ERROR "tessera was imported from ${where}, not ${prefix}/python/tessera")
endif()
# The installed plugin, loaded by pvbatch, with the filters' library beside it in the prefix (its
# runpath is relative: a trial's copy of a build tree loaded the library of the tree it was built
# in); a missing library fails LoadPlugin.
file(WRITE ${WORK_DIR}/plugin.py "import sys\nfrom paraview.simple import LoadPlugin\n"
  "LoadPlugin(sys.argv[1], remote=False, ns=globals())\n"
  "assert 'DirichletTessellation' in globals(), 'no filter'\n"
  "libraries = {line.split()[-1] for line in open('/proc/self/maps') if 'libtesseraFilters' in line}\n"
  "print('LOADED', *sorted(libraries))\n")
file(GLOB_RECURSE installed_plugin ${prefix}/*/Tessera.so)
if(NOT installed_plugin)
  message(FATAL_ERROR "no Tessera.so installed under ${prefix}")
endif()
run("loading the installed plugin" ${PVBATCH} ${WORK_DIR}/plugin.py ${installed_plugin})
file(GLOB installed_library ${prefix}/lib*/libtesseraFilters.so*)
list(GET installed_library 0 installed_library)
if(NOT output MATCHES "LOADED ${installed_library}\n")
  message(FATAL_ERROR "the installed plugin loaded the filters' library from elsewhere than "
    "${installed_library}:\n${output}")
endif()
message(STATUS "installed, found, built and run from ${prefix}")
