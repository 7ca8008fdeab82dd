# The CMake package (issue 17): `cmake --install` writes <lib>/cmake/fluidviz/ with
# fluidvizConfig.cmake, its version file and two sets of exported targets, all named fluidviz::
# after their module (fluidviz_lbm -> fluidviz::lbm):
#   fluidvizCoreTargets  the VTK-free layers: core, scene, particles, the solvers lbm and sph, the
#                        filter cores streamlines, topology, lic, isosurface, resample, probe.
#                        find_package(fluidviz CONFIG REQUIRED) loads these only; they need
#                        Eigen, OpenMP and nlohmann_json.
#   fluidvizVtkTargets   the VTK adapters and readers/writers (io) and the filters' VTK wrappers
#                        (*_vtk), loaded by COMPONENTS vtk, which finds Debian's VTK 9.1.
# Headers go to <include>/fluidviz/<folder>/, so consumers include them as this repository does
# ("solvers/lbm/LbmSolver.h"). The renderer (OSMesa link options, see fieldviz/CMakeLists.txt),
# the scene pipeline and the app are not exported.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(FLUIDVIZ_PACKAGE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/fluidviz)

# fluidviz_export(<set> <target>...): installs each target (and the headers of its folders, only
# those directly in a folder unless the module is RECURSE) into the export set fluidviz<set>Targets.
function(fluidviz_export set)
  foreach(target IN LISTS ARGN)
    string(REGEX REPLACE "^fluidviz_" "" name ${target})
    set_target_properties(${target} PROPERTIES EXPORT_NAME ${name})
    install(TARGETS ${target} EXPORT fluidviz${set}Targets
            ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
            LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
    get_target_property(dirs ${target} FLUIDVIZ_HEADER_DIRS)
    get_target_property(recurse ${target} FLUIDVIZ_HEADERS_RECURSE)
    foreach(dir IN LISTS dirs)
      if(recurse)
        install(DIRECTORY ${PROJECT_SOURCE_DIR}/${dir}/
                DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/fluidviz/${dir}
                FILES_MATCHING PATTERN "*.h")
      else()
        file(GLOB headers ${PROJECT_SOURCE_DIR}/${dir}/*.h)
        install(FILES ${headers} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/fluidviz/${dir})
      endif()
    endforeach()
  endforeach()
  install(EXPORT fluidviz${set}Targets NAMESPACE fluidviz::
          DESTINATION ${FLUIDVIZ_PACKAGE_DIR})
endfunction()

fluidviz_export(Core fluidviz_core fluidviz_scene fluidviz_particles fluidviz_lbm fluidviz_sph
  fluidviz_streamlines fluidviz_topology fluidviz_lic fluidviz_isosurface fluidviz_resample
  fluidviz_probe)
fluidviz_export(Vtk fluidviz_io fluidviz_streamlines_vtk fluidviz_topology_vtk fluidviz_lic_vtk
  fluidviz_isosurface_vtk fluidviz_resample_vtk)

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/fluidvizConfig.cmake.in
  ${CMAKE_BINARY_DIR}/package/fluidvizConfig.cmake
  INSTALL_DESTINATION ${FLUIDVIZ_PACKAGE_DIR})
write_basic_package_version_file(${CMAKE_BINARY_DIR}/package/fluidvizConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/package/fluidvizConfig.cmake
              ${CMAKE_BINARY_DIR}/package/fluidvizConfigVersion.cmake
        DESTINATION ${FLUIDVIZ_PACKAGE_DIR})
