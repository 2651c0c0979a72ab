# The browser dashboard: the HTTP server needs cpp-httplib (Debian's libcpp-httplib-dev), the
# front-end npm and Node.js >= 18 (web/, built with Vite 6 into <build>/web/dist: Debian 12's own
# nodejs and npm do). AUTO builds what it finds; the
# solver-only configuration (a GPU machine without Debian's -dev packages) builds neither.
set(PORESPH_DASHBOARD AUTO CACHE STRING "Build the browser dashboard (server and front-end): AUTO, ON or OFF")
set(PORESPH_HAVE_HTTPLIB OFF)
set(PORESPH_HAVE_WEB OFF)
if(NOT PORESPH_DASHBOARD STREQUAL "OFF")
  pkg_check_modules(HTTPLIB QUIET IMPORTED_TARGET cpp-httplib)
  find_program(PORESPH_NPM npm)
  find_program(PORESPH_NODE node)
  set(PORESPH_NODE_VERSION 0)
  if(PORESPH_NODE)
    execute_process(COMMAND ${PORESPH_NODE} --version OUTPUT_VARIABLE PORESPH_NODE_VERSION OUTPUT_STRIP_TRAILING_WHITESPACE)
    string(REGEX REPLACE "^v" "" PORESPH_NODE_VERSION "${PORESPH_NODE_VERSION}")
  endif()
  if(HTTPLIB_FOUND)
    set(PORESPH_HAVE_HTTPLIB ON)
  elseif(PORESPH_DASHBOARD STREQUAL "ON")
    message(FATAL_ERROR "PORESPH_DASHBOARD=ON but cpp-httplib was not found (apt-get install libcpp-httplib-dev)")
  endif()
  # Vite 6 (and playwright-core 1.56, the browser tests') run on Node.js 18, Debian 12's own; their
  # later releases need Node.js 20.
  if(PORESPH_HAVE_HTTPLIB AND PORESPH_NPM AND PORESPH_NODE_VERSION VERSION_GREATER_EQUAL 18)
    set(PORESPH_HAVE_WEB ON)
  elseif(PORESPH_DASHBOARD STREQUAL "ON")
    message(FATAL_ERROR "PORESPH_DASHBOARD=ON but npm and Node.js >= 18 were not found (node: ${PORESPH_NODE_VERSION})")
  elseif(PORESPH_HAVE_HTTPLIB)
    message(WARNING "the dashboard's front-end is not built: it needs npm and Node.js >= 18 (node: ${PORESPH_NODE_VERSION})")
  endif()
endif()
message(STATUS "poresph dashboard: server ${PORESPH_HAVE_HTTPLIB}, front-end ${PORESPH_HAVE_WEB}")

set(PORESPH_WEB_DIST ${CMAKE_BINARY_DIR}/web/dist)
if(PORESPH_HAVE_WEB)
  set(WEB ${PROJECT_SOURCE_DIR}/web)
  file(GLOB PORESPH_WEB_SOURCES CONFIGURE_DEPENDS ${WEB}/src/*.js ${WEB}/src/*.css ${WEB}/index.html ${WEB}/vite.config.js)
  # npm ci only when the lock file changes (node_modules stays in web/, ignored by git).
  add_custom_command(
    OUTPUT ${CMAKE_BINARY_DIR}/web/npm-ci.stamp
    COMMAND ${PORESPH_NPM} ci --no-audit --no-fund --loglevel=error
    COMMAND ${CMAKE_COMMAND} -E touch ${CMAKE_BINARY_DIR}/web/npm-ci.stamp
    WORKING_DIRECTORY ${WEB}
    DEPENDS ${WEB}/package.json ${WEB}/package-lock.json
    COMMENT "Installing the dashboard's npm packages (web/)")
  add_custom_command(
    OUTPUT ${PORESPH_WEB_DIST}/index.html
    COMMAND ${PORESPH_NPM} run --silent build -- --outDir ${PORESPH_WEB_DIST} --emptyOutDir --logLevel error
    WORKING_DIRECTORY ${WEB}
    DEPENDS ${CMAKE_BINARY_DIR}/web/npm-ci.stamp ${PORESPH_WEB_SOURCES}
    COMMENT "Building the dashboard's front-end (Vite)")
  add_custom_target(poresph_web ALL DEPENDS ${PORESPH_WEB_DIST}/index.html)
endif()
