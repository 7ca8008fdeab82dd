# Layers (docs/design.md, "Layers"): fieldviz/ < solvers/, filters/ < pipeline/ < apps/.
#
# A module's headers are visible only to the targets that link it. Instead of putting the
# repository root on everybody's include path, each module's folder is linked into
# <build>/include/<target>/<folder> and that directory becomes the module's PUBLIC include
# directory. An `#include "pipeline/..."` from a solver therefore does not compile: the solver
# does not link fluidviz_pipeline, so no include directory it sees holds that folder.
# (Tests, benches and fuzz targets sit above every layer and keep the root on their path.)
# tests/check_layers.cmake checks the same rule by reading the sources, so a header that the
# build never compiles from the wrong side is caught too.
#
# fluidviz_module_headers(<target> <folder>...): <folder> relative to the repository root.
# Installed (cmake/FluidvizPackage.cmake), the same headers sit in <include>/fluidviz/<folder>.
function(fluidviz_module_headers target)
  set(root "${CMAKE_BINARY_DIR}/include/${target}")
  foreach(dir IN LISTS ARGN)
    set(link "${root}/${dir}")
    get_filename_component(parent "${link}" DIRECTORY)
    file(MAKE_DIRECTORY "${parent}")
    if(NOT IS_SYMLINK "${link}")
      file(CREATE_LINK "${PROJECT_SOURCE_DIR}/${dir}" "${link}" SYMBOLIC)
    endif()
  endforeach()
  target_include_directories(${target} PUBLIC "$<BUILD_INTERFACE:${root}>"
                                              "$<INSTALL_INTERFACE:include/fluidviz>")
  set_property(TARGET ${target} APPEND PROPERTY FLUIDVIZ_HEADER_DIRS ${ARGN})
endfunction()

# fluidviz_module(<target> <folder> [RECURSE] [LINK <libraries>...]): a library of <folder>/*.cpp
# (with RECURSE also those of its sub-folders, for a module split by role such as solvers/lbm)
# whose headers are <folder>'s: sub-folder headers are named "<folder>/<sub>/X.h" through the same
# include directory. A vtk/ sub-folder is never recursed into: it is the module's thin VTK wrapper,
# a module of its own (filters/sketch/vtk). Globs pick up new files; CONFIGURE_DEPENDS re-runs
# CMake when they appear.
function(fluidviz_module target dir)
  cmake_parse_arguments(PARSE_ARGV 2 mod "RECURSE" "" "LINK")
  if(mod_RECURSE)
    file(GLOB_RECURSE srcs CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${dir}/*.cpp)
    list(FILTER srcs EXCLUDE REGEX "^${PROJECT_SOURCE_DIR}/${dir}/vtk/")
  else()
    file(GLOB srcs CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${dir}/*.cpp)
  endif()
  add_library(${target} ${srcs})
  fluidviz_module_headers(${target} ${dir})
  set_property(TARGET ${target} PROPERTY FLUIDVIZ_HEADERS_RECURSE ${mod_RECURSE})
  target_link_libraries(${target} PUBLIC ${mod_LINK})
endfunction()
