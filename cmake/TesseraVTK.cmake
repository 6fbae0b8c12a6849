# The VTK module Tessera::Filters, built once against ParaView 5.11's VTK and used twice: by the
# Python package `tessera` and by the ParaView plugin `Tessera` (paraview_plugin/).
find_package(ParaView REQUIRED)
find_package(Python3 REQUIRED COMPONENTS Interpreter Development)

set(BUILD_SHARED_LIBS ON)

vtk_module_scan(
  MODULE_FILES ${CMAKE_SOURCE_DIR}/vtk_filters/vtk.module
  REQUEST_MODULES Tessera::Filters
  PROVIDES_MODULES tessera_modules
  ENABLE_TESTS OFF)

vtk_module_build(
  MODULES ${tessera_modules}
  INSTALL_EXPORT TesseraFilters
  CMAKE_DESTINATION ${TESSERA_CMAKE_DESTINATION}
  LIBRARY_DESTINATION ${CMAKE_INSTALL_LIBDIR}
  HEADERS_DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/tessera)

# Python package `tessera`: build/python/tessera/ holds the wrapped module and __init__.py.
set(TESSERA_PYTHON_DESTINATION python)
vtk_module_wrap_python(
  MODULES ${tessera_modules}
  TARGET Tessera::Python
  WRAPPED_MODULES tessera_wrapped_modules
  PYTHON_PACKAGE tessera
  MODULE_DESTINATION ${TESSERA_PYTHON_DESTINATION}
  CMAKE_DESTINATION ${TESSERA_CMAKE_DESTINATION}
  LIBRARY_DESTINATION ${CMAKE_INSTALL_LIBDIR}
  INSTALL_HEADERS OFF
  BUILD_STATIC OFF)
configure_file(${CMAKE_SOURCE_DIR}/vtk_filters/python/__init__.py
  ${CMAKE_BINARY_DIR}/${TESSERA_PYTHON_DESTINATION}/tessera/__init__.py COPYONLY)
install(FILES ${CMAKE_SOURCE_DIR}/vtk_filters/python/__init__.py
  DESTINATION ${TESSERA_PYTHON_DESTINATION}/tessera)
set(TESSERA_PYTHONPATH ${CMAKE_BINARY_DIR}/${TESSERA_PYTHON_DESTINATION})

# The ParaView plugin: build/lib/paraview-plugins/Tessera/Tessera.so
paraview_plugin_scan(
  PLUGIN_FILES ${CMAKE_SOURCE_DIR}/paraview_plugin/paraview.plugin
  PROVIDES_PLUGINS tessera_plugins
  ENABLE_BY_DEFAULT ON)
paraview_plugin_build(
  PLUGINS ${tessera_plugins}
  RUNTIME_DESTINATION ${CMAKE_INSTALL_BINDIR}
  LIBRARY_DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY_SUBDIRECTORY paraview-plugins)
# In the build tree too the plugin finds the filters' library by its installed runpath, relative
# to itself (lib/paraview-plugins/Tessera/../../), as the Python module does: a copy of a build
# tree loaded the library of the tree it was built in.
set_target_properties(Tessera PROPERTIES BUILD_WITH_INSTALL_RPATH ON)
set(TESSERA_PLUGIN_PATH ${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_LIBDIR}/paraview-plugins/Tessera/Tessera.so)
