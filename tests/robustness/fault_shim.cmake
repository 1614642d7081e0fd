# The LD_PRELOAD fault shim of the commit tests (tests/robustness/shim/):
# a plain shared library, never sanitized, so it can be preloaded into any build.
add_library(raylab_fault_shim SHARED ${CMAKE_CURRENT_LIST_DIR}/shim/fault_shim.cpp)
target_compile_options(raylab_fault_shim PRIVATE -Wall -Wextra)
target_link_libraries(raylab_fault_shim PRIVATE ${CMAKE_DL_LIBS})
add_dependencies(test_robustness raylab_fault_shim)
target_compile_definitions(test_robustness PRIVATE
  RAYLAB_FAULT_SHIM="$<TARGET_FILE:raylab_fault_shim>")
