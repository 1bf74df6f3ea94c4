# The Debian package (`./build.sh package`, or `cpack` in a build folder):
# hazardsensor_<version>_<arch>.deb, installing under /usr. Depends is computed by
# dpkg-shlibdeps from the shared libraries the programs link, plus python3 for the mission
# launcher's summary and picture; no MOOS installation is needed.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME hazardsensor)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "HazardSensor developers")
set(CPACK_PACKAGE_CONTACT "HazardSensor developers <hazardsensor@users.noreply.invalid>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "simulated side-looking sonar for MOOS-IvP hazard searches")
set(CPACK_PACKAGE_DESCRIPTION
"HazardSensor is a reimplementation of MOOS-IvP's uFldHazardSensor, the
shoreside simulator of a side-looking sonar that detects and classifies
objects on the sea floor, and of its companion gen_hazards. It is a drop-in
replacement for the original in a mission launched by pAntler: same command
line, configuration block, messages and AppCast.

The package holds the sensor, gen_hazards, an offline replay tool
(hazard_replay), a runner of whole missions over seeds (hazard_study), a
MOOSDB-compatible server (moosdb-lite), a command-line MOOS client
(moos-cli), a web viewer (pWebViewer), the demo mission's apps,
the demo missions with their launcher, man pages, and the engine as static
libraries with headers, a CMake package and a pkg-config file.
No MOOS installation is needed.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "python3")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "librsvg2-bin")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "chromium, libgeographiclib-dev, libglm-dev")
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
include(CPack)
