# Python tests of scripts/spd (SPD generators, NFF -> POV-Ray converter, PNG
# tool), a smoke run of scripts/bench-povray.py and the documents' links
# (scripts/check-doc-links.py); included at the end of tests/CMakeLists.txt.
# One ctest entry per TestCase class of tests/scripts/test_spd_scripts.py,
# docs.links for tests/scripts/test_doc_links.py and scripts.BenchBars for
# tests/scripts/test_bench_bars.py. The POV-Ray cases report "skipped" (ctest:
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
  # Every relative link of README.md and docs/*.md names a file and heading
  # that exist (scripts/check-doc-links.py), and the checker finds broken ones.
  add_test(NAME docs.links
           COMMAND ${Python3_EXECUTABLE} -B -m unittest -v test_doc_links
           WORKING_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/scripts)
  set_tests_properties(docs.links PROPERTIES ENVIRONMENT "PYTHONDONTWRITEBYTECODE=1")
  # scripts/bench-bars.py's readers of each bar's tool output and its verdicts.
  add_test(NAME scripts.BenchBars
           COMMAND ${Python3_EXECUTABLE} -B -m unittest -v test_bench_bars
           WORKING_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/scripts)
  set_tests_properties(scripts.BenchBars PROPERTIES ENVIRONMENT "PYTHONDONTWRITEBYTECODE=1")
else()
  message(WARNING "python3 not found: the tests of scripts/ are not registered (scripts/install-deps.sh installs it)")
endif()
