# mpirun tests of the distributed renderer; included at the end of
# tests/CMakeLists.txt (test_distributed itself is built by its generic loop).
#   "mpi: ..." test cases run inside test_distributed launched by mpirun (every
#   rank runs them; rank 0 compares with a single-process render);
#   "mpirun cli: ..." test cases start `mpirun ... raylab render` themselves.
# Both are skipped by plain test_distributed runs. (Test names avoid spaces:
# the project's cmake_minimum_required predates policy CMP0110.) Without MPI one test
# reports "skipped: MPI not available" (ctest shows it as Skipped, not failed).
get_property(raylab_mpi_enabled GLOBAL PROPERTY RAYLAB_MPI_ENABLED)
set(raylab_mpirun "")
if(raylab_mpi_enabled)
  if(MPIEXEC_EXECUTABLE)
    set(raylab_mpirun ${MPIEXEC_EXECUTABLE})
  else()
    find_program(raylab_mpirun NAMES mpirun mpiexec)
  endif()
endif()

if(raylab_mpi_enabled AND raylab_mpirun AND TARGET test_distributed)
  # Two ranks on however many cores there are; Open MPI also refuses to run
  # as root (containers, CI) unless told.
  set(raylab_mpirun_flags "")
  execute_process(COMMAND ${raylab_mpirun} --version OUTPUT_VARIABLE mpirun_version
                  ERROR_QUIET RESULT_VARIABLE mpirun_rc)
  if(mpirun_version MATCHES "Open MPI|OpenRTE")
    set(raylab_mpirun_flags --oversubscribe --allow-run-as-root)
  endif()
  add_test(NAME distributed.mpirun_np2_library
           COMMAND ${raylab_mpirun} -np 2 ${raylab_mpirun_flags}
                   $<TARGET_FILE:test_distributed> --test-case=mpi:*
           WORKING_DIRECTORY ${CMAKE_BINARY_DIR})
  list(JOIN raylab_mpirun_flags " " flags_text)
  add_test(NAME distributed.mpirun_np2_raylab_render
           COMMAND $<TARGET_FILE:test_distributed> --test-case=mpirun?cli:*
           WORKING_DIRECTORY ${CMAKE_BINARY_DIR})
  set_tests_properties(distributed.mpirun_np2_raylab_render PROPERTIES
    ENVIRONMENT "RAYLAB_MPIRUN=${raylab_mpirun};RAYLAB_MPIRUN_FLAGS=${flags_text}")
  # Several processes each: keep them off the other tests' cores.
  set_tests_properties(distributed.mpirun_np2_library
                       distributed.mpirun_np2_raylab_render
                       PROPERTIES RUN_SERIAL TRUE TIMEOUT 900)
  if(RAYLAB_SANITIZE)
    # Open MPI never frees its own allocations at MPI_Finalize (~121 KB per rank).
    set_property(TEST distributed.mpirun_np2_library distributed.mpirun_np2_raylab_render
                 APPEND PROPERTY ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0")
  endif()
else()
  if(NOT raylab_mpi_enabled)
    string(CONCAT why "raylab built without MPI (RAYLAB_MPI=OFF or MPI not found; "
                      "apt-get install libopenmpi-dev openmpi-bin)")
  else()
    set(why "no mpirun/mpiexec found (apt-get install openmpi-bin)")
  endif()
  add_test(NAME distributed.mpirun_skipped_without_mpi
           COMMAND sh -c "echo 'skipped: MPI not available: ${why}'; exit 77")
  set_tests_properties(distributed.mpirun_skipped_without_mpi
                       PROPERTIES SKIP_RETURN_CODE 77)
endif()
