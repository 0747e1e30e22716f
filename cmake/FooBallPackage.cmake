# CPack: a Debian package of what `cmake --install` puts in place (scripts/package builds it;
# tests/packaging checks it). Included last, once every install rule exists.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME fooball)
set(CPACK_PACKAGE_VENDOR "The FooBall team")
# .invalid (RFC 2606): the package names a maintainer, but there is no address to write to yet.
set(CPACK_PACKAGE_CONTACT "The FooBall team <team@fooball.invalid>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "compare how physics methods treat bouncing balls")
# The extended description, below the summary line (CPack indents it and marks the empty line).
set(CPACK_PACKAGE_DESCRIPTION
    "FooBall runs one box of balls on interchangeable physics methods (a time-stepped
elastic solver, Box2D, Chipmunk2D and Bullet with restitution 1, small-steps XPBD
and an exact event-driven solver) in lockstep, side by side, and charts what each
does to momentum and energy.

This package holds the desktop app, fooball, and the headless simulator,
fooball-cli.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_STRIP_FILES ON)
# The shared libraries come from dpkg-shlibdeps. What the programs load at run time without
# linking to it: Qt's platform plugins (xcb for a desktop, offscreen for --frames), and a font for
# the charts' text; and Node.js, which runs the engines in JavaScript and WebAssembly (their npm
# packages ship in share/fooball/js).
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "qt6-qpa-plugins, fonts-dejavu-core, nodejs (>= 18)")
include(CPack)
