# Python tests of scripts/spd (SPD generators, NFF -> POV-Ray converter, PNG
# tool) and a smoke run of scripts/bench-povray.py; included at the end of
# tests/CMakeLists.txt. One ctest entry per TestCase class of
# tests/scripts/test_spd_scripts.py. The POV-Ray cases report "skipped" (ctest:
# Skipped) when povray, an optional package, is not installed. None of them
# needs ../shared or the network.
find_package(Python3 COMPONENTS Interpreter)
if(Python3_Interpreter_FOUND)
  foreach(case Generators Nff2Pov EarClip PngTool WithPovray)
    add_test(NAME scripts.${case}
             COMMAND ${Python3_EXECUTABLE} -B -m unittest -v test_spd_scripts.${case}
             WORKING_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/scripts)
    set_tests_properties(scripts.${case} PROPERTIES
      ENVIRONMENT "RAYLAB_BINARY=$<TARGET_FILE:raylab>;PYTHONDONTWRITEBYTECODE=1")
  endforeach()
  set_tests_properties(scripts.WithPovray PROPERTIES SKIP_REGULAR_EXPRESSION "OK \\(skipped=")
else()
  message(WARNING "python3 not found: the tests of scripts/ are not registered (scripts/install-deps.sh installs it)")
endif()
