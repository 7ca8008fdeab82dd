# Fails if a VTK header is included where the design forbids it: solvers/, fieldviz/core,
# fieldviz/scene, fieldviz/resample, and filter cores (filters/<name>/ outside filters/<name>/vtk/).
# Run as: cmake -DSOURCE_DIR=<repo> -P check_no_vtk.cmake
file(GLOB_RECURSE candidates
  ${SOURCE_DIR}/solvers/*.h ${SOURCE_DIR}/solvers/*.cpp
  ${SOURCE_DIR}/fieldviz/core/*.h ${SOURCE_DIR}/fieldviz/core/*.cpp
  ${SOURCE_DIR}/fieldviz/scene/*.h ${SOURCE_DIR}/fieldviz/scene/*.cpp
  ${SOURCE_DIR}/fieldviz/resample/*.h ${SOURCE_DIR}/fieldviz/resample/*.cpp
  ${SOURCE_DIR}/filters/*.h ${SOURCE_DIR}/filters/*.cpp)
set(offenders "")
foreach(f IN LISTS candidates)
  if(f MATCHES "/(filters/[^/]+|fieldviz/resample)/vtk/")
    continue()
  endif()
  file(STRINGS ${f} hits REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"]vtk")
  if(hits)
    list(APPEND offenders "${f}: ${hits}")
  endif()
endforeach()
list(LENGTH candidates checked)
if(offenders)
  string(REPLACE ";" "\n  " text "${offenders}")
  message(FATAL_ERROR "VTK headers in VTK-free code:\n  ${text}")
endif()
message(STATUS "checked ${checked} VTK-free source files: no VTK includes")
