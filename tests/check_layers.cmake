cmake_minimum_required(VERSION 3.25)
# The layering rule of docs/design.md, read from the sources (the build enforces it too, through
# cmake/FluidvizLayers.cmake): each top-level folder includes only headers of the folders below it,
#
#   fieldviz/core  <  fieldviz/*  <  solvers/, filters/  <  pipeline/  <  apps/, paraview/
#
# (paraview/, the ParaView plugin, uses fieldviz/ and filters/ today; paraview/properties stays
# VTK-free, like the cores, because the main build compiles and tests it.)
# (solvers/ and filters/ do not use each other), and VTK headers stay out of the VTK-free code:
# solvers/, fieldviz/core, fieldviz/scene, fieldviz/particles and the filter cores (filters/<name>/
# outside filters/<name>/vtk/). Nothing in the library layers includes tests/ or bench/.
# Run as: cmake -DSOURCE_DIR=<repo> -P check_layers.cmake
set(layers fieldviz solvers filters pipeline apps paraview)
set(allowed_fieldviz fieldviz)
set(allowed_solvers fieldviz solvers)
set(allowed_filters fieldviz filters)
set(allowed_pipeline fieldviz solvers filters pipeline)
set(allowed_apps fieldviz solvers filters pipeline apps)
set(allowed_paraview fieldviz solvers filters pipeline paraview)

set(offenders "")
set(checked 0)
foreach(layer IN LISTS layers)
  file(GLOB_RECURSE files ${SOURCE_DIR}/${layer}/*.h ${SOURCE_DIR}/${layer}/*.cpp)
  foreach(f IN LISTS files)
    math(EXPR checked "${checked} + 1")
    file(RELATIVE_PATH rel ${SOURCE_DIR} ${f})
    file(STRINGS ${f} includes REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"]")
    foreach(line IN LISTS includes)
      string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*[<\"]([^>\"]*)[>\"].*" "\\1" header "${line}")
      # Project headers are named from the repository root: "<folder>/...".
      string(REGEX MATCH "^[^/]+" top "${header}")
      if(top MATCHES "^(fieldviz|solvers|filters|pipeline|apps|paraview|tests|bench)$")
        if(NOT top IN_LIST allowed_${layer})
          list(APPEND offenders "${rel} (layer ${layer}/) includes ${header}, a header of ${top}/")
        elseif(rel MATCHES "^fieldviz/core/" AND NOT header MATCHES "^fieldviz/core/")
          list(APPEND offenders "${rel} (fieldviz/core, the bottom) includes ${header}")
        endif()
      endif()
      # VTK-free code.
      if(header MATCHES "^vtk" AND rel MATCHES "^(solvers/|fieldviz/(core|scene|particles)/|filters/|paraview/(properties|generator)/)"
         AND NOT rel MATCHES "^filters/[^/]+/vtk/")
        list(APPEND offenders "${rel} includes the VTK header ${header} in VTK-free code")
      endif()
    endforeach()
  endforeach()
endforeach()
if(offenders)
  string(REPLACE ";" "\n  " text "${offenders}")
  message(FATAL_ERROR "layering rule broken (docs/design.md, \"Layers\"):\n  ${text}")
endif()
message(STATUS "checked ${checked} source files of ${layers}: every include goes downwards, no VTK in VTK-free code")
