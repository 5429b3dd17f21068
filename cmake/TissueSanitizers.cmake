# TISSUE_SANITIZE: sanitizers for every target of the tree, e.g. "address,undefined" (ASan with
# LSan, and UBSan). scripts/run-tests.sh builds its second tree this way (tests/package/
# no_vtk_build.sh, build-san/); findings stop the test (-fno-sanitize-recover), and line tables (-g1) give
# the reports file:line. Everything is compiled with the flags, so no uninstrumented tissue code
# runs; the system libraries (Mesa, glibc) are not instrumented and their leaks are suppressed by
# tests/sanitizers/lsan.supp.
set(TISSUE_SANITIZE "" CACHE STRING "Sanitizers for every target (e.g. address,undefined); empty: none")
# Window tests (GLFW under Xvfb) in a sanitized tree: GLFW dlopens the GLX and X libraries and
# unloads them at glfwTerminate, so LeakSanitizer reports their caches with <unknown module>
# frames that no suppression can name. tissue_sanitized_window_test(NAME) keeps ASan and UBSan on
# for such a test and turns only the leak check off (tests/package/no_vtk_build.sh sets the rest).
function(tissue_sanitized_window_test name)
  if(TISSUE_SANITIZE)
    set_property(TEST ${name} APPEND PROPERTY ENVIRONMENT
                 "ASAN_OPTIONS=detect_leaks=0:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1")
  endif()
endfunction()
if(TISSUE_SANITIZE)
  add_compile_options(-fsanitize=${TISSUE_SANITIZE} -fno-sanitize-recover=all -fno-omit-frame-pointer -g1)
  add_link_options(-fsanitize=${TISSUE_SANITIZE})
endif()

# TISSUE_FUZZ: the libFuzzer targets of tests/fuzz (clang only). Every target of the tree gets
# libFuzzer's coverage instrumentation (-fsanitize=fuzzer-no-link), so the fuzzers are guided
# through the library's code and not only the harness; combine with TISSUE_SANITIZE.
option(TISSUE_FUZZ "Build the libFuzzer targets of tests/fuzz (needs clang)" OFF)
if(TISSUE_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "TISSUE_FUZZ needs clang (libFuzzer): configure with -DCMAKE_C_COMPILER=clang "
                        "-DCMAKE_CXX_COMPILER=clang++, or turn TISSUE_FUZZ off")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
