# What `cmake --install` puts where (GNUInstallDirs under the prefix):
#   bin/                          the programs (cmake/programs.cmake)
#   lib/                          the engine's static libraries, libhazardsensor-*.a
#   include/hazardsensor/         their public headers (base/, hazard/)
#   lib/cmake/HazardSensor/       find_package(HazardSensor CONFIG): HazardSensor::hazard,
#                                 HazardSensor::base, with a version file
#   lib/pkgconfig/hazardsensor.pc the same for pkg-config
#   share/man/man1/               a man page per program
#   share/doc/hazardsensor/       README, CHANGELOG, copyright, changelog.gz, docs/
#   share/hazardsensor/           the demo missions and the tools their launcher runs
set(HAZARD_INSTALL_INCLUDEDIR ${CMAKE_INSTALL_INCLUDEDIR}/hazardsensor)
# Folders the install creates are 0755 whatever the umask of whoever installs or packages.
set(CMAKE_INSTALL_DEFAULT_DIRECTORY_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ
    GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)
set(HAZARD_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/HazardSensor)
set(HAZARD_INSTALL_DATADIR ${CMAKE_INSTALL_DATADIR}/hazardsensor)
set(HAZARD_INSTALL_DOCDIR ${CMAKE_INSTALL_DATADIR}/doc/hazardsensor)

# The engine and what it needs below it, as a consumer links them.
set(HAZARD_EXPORTED_LIBRARIES base hazard)
foreach(library ${HAZARD_EXPORTED_LIBRARIES})
  # Installed names say whose they are (a bare libbase.a would clash in /usr/lib).
  set_target_properties(${library} PROPERTIES OUTPUT_NAME hazardsensor-${library}
                                              EXPORT_NAME ${library}
                                              POSITION_INDEPENDENT_CODE ON)
endforeach()
install(TARGETS ${HAZARD_EXPORTED_LIBRARIES} EXPORT HazardSensorTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT development
        INCLUDES DESTINATION ${HAZARD_INSTALL_INCLUDEDIR})
install(DIRECTORY include/base include/hazard DESTINATION ${HAZARD_INSTALL_INCLUDEDIR}
        COMPONENT development)
install(EXPORT HazardSensorTargets NAMESPACE HazardSensor:: DESTINATION ${HAZARD_INSTALL_CMAKEDIR}
        COMPONENT development)

include(CMakePackageConfigHelpers)
configure_package_config_file(cmake/HazardSensorConfig.cmake.in
  ${PROJECT_BINARY_DIR}/HazardSensorConfig.cmake INSTALL_DESTINATION ${HAZARD_INSTALL_CMAKEDIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/HazardSensorConfigVersion.cmake
  COMPATIBILITY SameMajorVersion)
install(FILES ${PROJECT_BINARY_DIR}/HazardSensorConfig.cmake
              ${PROJECT_BINARY_DIR}/HazardSensorConfigVersion.cmake
        DESTINATION ${HAZARD_INSTALL_CMAKEDIR} COMPONENT development)

# pkg-config: the prefix is found from the file's own place, so any install prefix works.
file(RELATIVE_PATH HAZARD_PC_TO_PREFIX /${CMAKE_INSTALL_LIBDIR}/pkgconfig /)
configure_file(cmake/hazardsensor.pc.in ${PROJECT_BINARY_DIR}/hazardsensor.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/hazardsensor.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig
        COMPONENT development)

# Docs. The Debian changelog is stored compressed, as Debian's policy asks.
# (The copyright file names the licence; Debian keeps the licence's text in common-licenses.)
install(FILES README.md CHANGELOG.md packaging/copyright DESTINATION ${HAZARD_INSTALL_DOCDIR}
        COMPONENT documentation)
install(DIRECTORY docs/ DESTINATION ${HAZARD_INSTALL_DOCDIR}/docs COMPONENT documentation
        PATTERN .keep EXCLUDE)
set(HAZARD_DEBIAN_CHANGELOG ${PROJECT_BINARY_DIR}/changelog.gz)
add_custom_command(
  OUTPUT ${HAZARD_DEBIAN_CHANGELOG}
  COMMAND gzip -9nc ${PROJECT_SOURCE_DIR}/packaging/changelog > ${HAZARD_DEBIAN_CHANGELOG}
  DEPENDS ${PROJECT_SOURCE_DIR}/packaging/changelog
  COMMENT "Compressing the Debian changelog")
add_custom_target(debian_changelog ALL DEPENDS ${HAZARD_DEBIAN_CHANGELOG})
install(FILES ${HAZARD_DEBIAN_CHANGELOG} DESTINATION ${HAZARD_INSTALL_DOCDIR}
        COMPONENT documentation)

# The demo missions and what their launcher runs after a mission (summary, picture).
install(DIRECTORY missions/ DESTINATION ${HAZARD_INSTALL_DATADIR}/missions COMPONENT missions
        USE_SOURCE_PERMISSIONS PATTERN __pycache__ EXCLUDE)
install(DIRECTORY tools/ DESTINATION ${HAZARD_INSTALL_DATADIR}/tools COMPONENT missions
        USE_SOURCE_PERMISSIONS PATTERN __pycache__ EXCLUDE)
