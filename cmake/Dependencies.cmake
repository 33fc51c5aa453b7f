# Every dependency is a Debian 12 package. A missing one stops the configuration with the
# package name to install (scripts/setup.sh installs them all).
include(FindPkgConfig)

macro(soilsph_require package debian_package)
  find_package(${package} ${ARGN} QUIET)
  if(NOT ${package}_FOUND)
    message(FATAL_ERROR "soilsph needs ${package}: install it with `apt-get install ${debian_package}` "
                        "(or run scripts/setup.sh, which installs every dependency).")
  endif()
endmacro()

soilsph_require(Eigen3 libeigen3-dev 3.4 NO_MODULE)
soilsph_require(SUNDIALS libsundials-dev)
soilsph_require(GSL libgsl-dev)
soilsph_require(HDF5 libhdf5-dev COMPONENTS C)
soilsph_require(CLI11 libcli11-dev)
soilsph_require(OpenMP "g++ (libgomp1)")

find_package(PkgConfig QUIET)
if(PkgConfig_FOUND)
  pkg_check_modules(TOMLPP QUIET IMPORTED_TARGET tomlplusplus)
endif()
if(NOT TOMLPP_FOUND)
  message(FATAL_ERROR "soilsph needs toml++: install it with `apt-get install libtomlplusplus-dev pkg-config`.")
endif()

if(SOILSPH_BUILD_TESTS)
  soilsph_require(Catch2 catch2)
endif()
if(SOILSPH_BUILD_BENCHMARKS)
  soilsph_require(benchmark libbenchmark-dev)
endif()
