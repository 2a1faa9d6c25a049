# Sourced by the scripts that configure a build folder (build.sh, test.sh, fuzz.sh): new folders
# are Ninja's. With CMake's Makefiles a target's files wait until every library it links is
# built, so at each library boundary one core idles; Ninja starts a file as soon as its inputs
# exist. The sanitizer and fuzz build on the 2-core AMD EPYC (Zen 3), the same sources: 457 s
# with Makefiles, 425 s with Ninja, the same 805 s of compiler time (docs/speed.md, "Build
# time"). A folder configured before keeps its generator: CMake reads CMAKE_GENERATOR only for
# a new one. Set CMAKE_GENERATOR to choose another.
export CMAKE_GENERATOR=${CMAKE_GENERATOR:-Ninja}
