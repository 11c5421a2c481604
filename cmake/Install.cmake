# `cmake --install`: the libraries behind vplant::vplant, the public headers (include/vplant/),
# the `vplant` CLI, the products' EDS files, the scenarios and the docs; an exported CMake package
# (vplantConfig.cmake + version file) for find_package(vplant). Layout under the prefix:
#   bin/vplant                      lib/libvplant_*.a             lib/cmake/vplant/
#   include/vplant/*.h              share/vplant/eds/*.eds        share/vplant/scenarios/
#   share/doc/vplant/ (README.md, docs/)
include(CMakePackageConfigHelpers)
# Install and package what is built (`cmake --build` first): CPack's preinstall step then does
# not rebuild the whole tree, tests included, one job at a time.
set(CMAKE_SKIP_INSTALL_ALL_DEPENDENCY ON)

# The static libraries vplant_api links, transitively: a consumer links them all, so the export
# must name each (a library another part of the tree adds to the engine follows automatically).
function(_vplant_link_closure target out)
  set(seen "")
  set(to_visit ${target})
  while(to_visit)
    list(POP_FRONT to_visit t)
    if(NOT TARGET ${t} OR t IN_LIST seen)
      continue()
    endif()
    get_target_property(imported ${t} IMPORTED)
    get_target_property(aliased ${t} ALIASED_TARGET)
    if(imported OR aliased)
      continue()
    endif()
    list(APPEND seen ${t})
    get_target_property(deps ${t} LINK_LIBRARIES)
    get_target_property(ideps ${t} INTERFACE_LINK_LIBRARIES)
    foreach(d IN LISTS deps ideps)
      string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" d "${d}")
      if(d AND TARGET ${d})
        list(APPEND to_visit ${d})
      endif()
    endforeach()
  endwhile()
  set(${out} ${seen} PARENT_SCOPE)
endfunction()
_vplant_link_closure(vplant_api vplant_export_targets)

set(VPLANT_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/vplant)
install(TARGETS ${vplant_export_targets} EXPORT vplantTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
# `cmake --install --strip` and CPack (CPACK_STRIP_FILES) strip executables only; drop the static
# libraries' debug information too (their symbols stay: they are linked from): the package
# shrinks from about 220 MB to a tenth.
find_program(VPLANT_STRIP NAMES ${CMAKE_STRIP} strip)
foreach(t ${vplant_export_targets})
  install(CODE "if(CMAKE_INSTALL_DO_STRIP)
  execute_process(COMMAND \"${VPLANT_STRIP}\" --strip-debug \"\$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_LIBDIR}/$<TARGET_FILE_NAME:${t}>\")
endif()")
endforeach()
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/vplant DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT vplantTargets NAMESPACE vplant:: DESTINATION ${VPLANT_CMAKE_DIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/vplantConfig.cmake.in
  ${PROJECT_BINARY_DIR}/vplantConfig.cmake
  INSTALL_DESTINATION ${VPLANT_CMAKE_DIR}
  PATH_VARS CMAKE_INSTALL_DATADIR)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/vplantConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/vplantConfig.cmake ${PROJECT_BINARY_DIR}/vplantConfigVersion.cmake
        DESTINATION ${VPLANT_CMAKE_DIR})

install(TARGETS vplant RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
file(GLOB vplant_product_eds ${PROJECT_SOURCE_DIR}/devices/*/*.eds)
install(FILES ${vplant_product_eds} DESTINATION ${CMAKE_INSTALL_DATADIR}/vplant/eds)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/scenarios/ DESTINATION ${CMAKE_INSTALL_DATADIR}/vplant/scenarios)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/exercises/ DESTINATION ${CMAKE_INSTALL_DATADIR}/vplant/exercises)
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR})
