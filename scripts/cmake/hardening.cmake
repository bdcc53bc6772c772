# Debian's hardening flags (as dpkg-buildflags gives them with hardening=+all) for the Release
# build, the one the package is made from: fortified libc calls, stack protector, format checks,
# read-only relocations bound at start. The sanitizer and fuzzer presets build RelWithDebInfo and
# keep their own instrumentation instead (ASan replaces the checks _FORTIFY_SOURCE adds).
option(CHAPLYGIN_HARDENING "Debian's hardening flags in the Release build" ON)
if(CHAPLYGIN_HARDENING AND CMAKE_BUILD_TYPE STREQUAL "Release")
  add_compile_definitions(_FORTIFY_SOURCE=2)
  add_compile_options(-fstack-protector-strong -Wformat -Werror=format-security)
  add_link_options(-Wl,-z,relro -Wl,-z,now)
endif()
add_feature_info(Hardening CHAPLYGIN_HARDENING "Debian's hardening flags in Release (dpkg-buildflags)")
