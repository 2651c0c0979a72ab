# Header-only dependencies: toml++, CLI11, nlohmann-json; GoogleTest for the tests.
# Normally Debian's packages (toml++ through pkg-config, the others through their CMake files).
# With PORESPH_DEPS_DIR, a folder made by scripts/gpu-deps.sh (a GPU machine without Debian's -dev
# packages or pkg-config), only the copies in that folder are used: toml++ header-only, GoogleTest
# built from its sources. Thrust/CUB always come with CUDA (CCCL) in a CUDA build.
set(PORESPH_DEPS_DIR "" CACHE PATH "Folder of carried header-only dependencies (scripts/gpu-deps.sh); empty: the system's")

if(PORESPH_DEPS_DIR)
  foreach(f include/toml++/toml.h include/CLI/CLI.hpp include/nlohmann/json.hpp googletest/CMakeLists.txt)
    if(NOT EXISTS ${PORESPH_DEPS_DIR}/${f})
      message(FATAL_ERROR "PORESPH_DEPS_DIR=${PORESPH_DEPS_DIR} has no ${f}: make it with scripts/gpu-deps.sh")
    endif()
  endforeach()
  # Same target names as the system's packages give, so that the solver links one name either way.
  foreach(t PkgConfig::TOMLPP CLI11::CLI11 nlohmann_json::nlohmann_json)
    add_library(${t} INTERFACE IMPORTED)
    set_target_properties(${t} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES ${PORESPH_DEPS_DIR}/include)
  endforeach()
  set_target_properties(PkgConfig::TOMLPP PROPERTIES INTERFACE_COMPILE_DEFINITIONS TOML_HEADER_ONLY=1)
  find_package(PkgConfig QUIET)  # optional here: only the dashboard's AUTO asks it
  message(STATUS "poresph: toml++, CLI11, nlohmann-json from ${PORESPH_DEPS_DIR}")
else()
  find_package(PkgConfig REQUIRED)
  pkg_check_modules(TOMLPP REQUIRED IMPORTED_TARGET tomlplusplus)
  find_package(CLI11 REQUIRED)
  find_package(nlohmann_json 3.10 REQUIRED)
endif()

# GTest::gtest_main for the tests: the system's, or built from the carried sources.
macro(poresph_find_gtest)
  if(PORESPH_DEPS_DIR)
    set(BUILD_GMOCK OFF)
    set(INSTALL_GTEST OFF)
    add_subdirectory(${PORESPH_DEPS_DIR}/googletest ${CMAKE_BINARY_DIR}/googletest EXCLUDE_FROM_ALL)
  else()
    find_package(GTest REQUIRED)
  endif()
endmacro()
