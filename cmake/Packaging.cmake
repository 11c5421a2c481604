# CPack: `cpack -G DEB` in the build tree makes vplant_<version>_<arch>.deb from the install rules
# (cmake/Install.cmake), under /usr. Depends: the Debian runtime packages of the CLI's shared
# libraries, computed by dpkg-shlibdeps (libyaml-cpp0.7, libode8, libfmt9, ...).
# Recommends: the -dev packages find_package(vplant) needs to link the static libraries.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME vplant)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "vplant")
set(CPACK_PACKAGE_CONTACT "vplant maintainers <vplant@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "multi-node virtual plant simulator: emulated CANopen nodes and hydraulic physics")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_PACKAGE_SECTION devel)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_COMPRESSION_TYPE gzip)  # fast; xz saves little on stripped objects
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS
    "libyaml-cpp-dev, libfmt-dev, libeigen3-dev, libode-dev, nlohmann-json3-dev, pkg-config, cmake, g++")
find_program(VPLANT_DPKG dpkg)
if(VPLANT_DPKG)
  execute_process(COMMAND ${VPLANT_DPKG} --print-architecture OUTPUT_VARIABLE vplant_deb_arch OUTPUT_STRIP_TRAILING_WHITESPACE)
else()
  set(vplant_deb_arch amd64)
endif()
set(CPACK_DEBIAN_PACKAGE_ARCHITECTURE ${vplant_deb_arch})
set(CPACK_DEBIAN_FILE_NAME "vplant_${PROJECT_VERSION}_${vplant_deb_arch}.deb")
include(CPack)
