# Distributed rendering over MPI (docs/distributed.md). Included by
# renderer/CMakeLists.txt after raylab_renderer is defined. The sources of
# this folder are already part of raylab_renderer (its GLOB_RECURSE); this
# fragment decides whether they talk MPI:
#   RAYLAB_MPI=ON (default) and MPI found -> RAYLAB_HAVE_MPI=1, linked to MPI::MPI_CXX;
#   otherwise -> the build without MPI: single-process rendering only, and a
#   launch under mpirun stops with "built without MPI".
option(RAYLAB_MPI "Distributed rendering across processes with MPI (mpirun -np N raylab render)" ON)

set(RAYLAB_MPI_ENABLED OFF)
if(RAYLAB_MPI)
  find_package(MPI COMPONENTS CXX QUIET)
  if(MPI_CXX_FOUND)
    set(RAYLAB_MPI_ENABLED ON)
    message(STATUS "raylab: distributed rendering with MPI ${MPI_CXX_VERSION} (RAYLAB_MPI=ON)")
  else()
    message(STATUS "raylab: MPI not found (apt-get install libopenmpi-dev openmpi-bin): "
                   "building without distributed rendering")
  endif()
else()
  message(STATUS "raylab: distributed rendering disabled (RAYLAB_MPI=OFF)")
endif()

if(RAYLAB_MPI_ENABLED)
  target_link_libraries(raylab_renderer PRIVATE MPI::MPI_CXX)
  target_compile_definitions(raylab_renderer PRIVATE RAYLAB_HAVE_MPI=1)
endif()
# For tests/distributed/mpi_tests.cmake, which runs in another directory scope.
set_property(GLOBAL PROPERTY RAYLAB_MPI_ENABLED ${RAYLAB_MPI_ENABLED})
