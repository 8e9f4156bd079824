# grassfireDependencies.cmake -- what grassfire_kernel's headers and archive need, found the
# same way when grassfire is built and when a consumer loads the installed package
# (grassfireConfig.cmake includes this file). CGAL is not here: the kernel uses it only
# inside .cpp files, so consumers neither compile nor find it.
find_package(Boost 1.74 REQUIRED)              # Boost.Graph in medial2/medial_graph.h (headers only)
find_package(nlohmann_json 3 REQUIRED)         # reports in io/ and complex3/builders/
find_package(PNG REQUIRED)                     # binary images as shapes (io/shape_image.h)
find_package(GIF 5 REQUIRED)
find_library(GRASSFIRE_GMPXX_LIBRARY gmpxx REQUIRED)
find_library(GRASSFIRE_GMP_LIBRARY gmp REQUIRED)
find_library(GRASSFIRE_MPFR_LIBRARY mpfr REQUIRED)
find_library(GRASSFIRE_ARB_LIBRARY NAMES flint-arb arb REQUIRED)
find_library(GRASSFIRE_FLINT_LIBRARY flint REQUIRED)

# Exact numbers (number/): GMP rationals, MPFR, Arb balls over FLINT. One imported target,
# so that the exported kernel names it instead of this machine's library paths.
if(NOT TARGET grassfire::number_libraries)
  add_library(grassfire::number_libraries INTERFACE IMPORTED)
  set_target_properties(grassfire::number_libraries PROPERTIES INTERFACE_LINK_LIBRARIES
    "${GRASSFIRE_ARB_LIBRARY};${GRASSFIRE_FLINT_LIBRARY};${GRASSFIRE_GMPXX_LIBRARY};${GRASSFIRE_MPFR_LIBRARY};${GRASSFIRE_GMP_LIBRARY}")
endif()
