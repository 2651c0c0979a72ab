# ParaView 5.11 from Debian: VTK for VTP output, legacy Catalyst for the in-situ pipelines.
# Its exported targets name X11::X11, Freetype::Freetype, GLEW::GLEW, Boost::boost,
# LibXml2::LibXml2, MPI::MPI_C, NetCDF::NetCDF and hdf5::hdf5 without finding them, so they are
# found here first (with ParaView's own Find modules from its cmake/vtk folder).
set(PORESPH_HAVE_PARAVIEW OFF)
set(PORESPH_HAVE_CATALYST OFF)
if(PORESPH_PARAVIEW STREQUAL "OFF")
  return()
endif()

find_path(PORESPH_PARAVIEW_VTK_CMAKE FindNetCDF.cmake
  HINTS ${ParaView_DIR}/vtk
  PATHS /usr/lib/x86_64-linux-gnu/cmake/paraview-5.11/vtk /usr/lib/cmake/paraview-5.11/vtk)
if(PORESPH_PARAVIEW_VTK_CMAKE)
  list(APPEND CMAKE_MODULE_PATH ${PORESPH_PARAVIEW_VTK_CMAKE})
endif()
set(_pv_deps_found ON)
foreach(dep X11 Freetype GLEW Boost LibXml2 NetCDF)
  find_package(${dep} QUIET)
  if(NOT ${dep}_FOUND)
    set(_pv_deps_found OFF)
  endif()
endforeach()
find_package(MPI QUIET COMPONENTS C)
find_package(HDF5 QUIET COMPONENTS C HL)
if(NOT MPI_FOUND OR NOT HDF5_FOUND)
  set(_pv_deps_found OFF)
endif()

if(_pv_deps_found)
  find_package(ParaView QUIET COMPONENTS Catalyst PythonCatalyst VTKExtensionsCore)
endif()
if(ParaView_FOUND)
  set(PORESPH_HAVE_PARAVIEW ON)
  set(PORESPH_HAVE_CATALYST ON)
  find_program(PORESPH_PVBATCH pvbatch HINTS ${ParaView_PREFIX_PATH}/bin)
  message(STATUS "poresph: ParaView ${ParaView_VERSION} found: VTP output and Catalyst pipelines")
elseif(PORESPH_PARAVIEW STREQUAL "ON")
  message(FATAL_ERROR "PORESPH_PARAVIEW=ON but ParaView with Catalyst was not found (set ParaView_DIR; "
                      "on Debian 12 run scripts/install-deps.sh)")
else()
  message(STATUS "poresph: ParaView not found, solver-only build (no VTP output, no Catalyst)")
endif()
