# TISSUE_SANITIZE: sanitizers for every target of the tree, e.g. "address,undefined" (ASan with
# LSan, and UBSan). scripts/run-tests.sh builds its second tree this way (tests/package/
# sanitized_build.sh); findings stop the test (-fno-sanitize-recover), and line tables (-g1) give
# the reports file:line. Everything is compiled with the flags, so no uninstrumented tissue code
# runs; the system libraries (Mesa, glibc) are not instrumented and their leaks are suppressed by
# tests/sanitizers/lsan.supp.
set(TISSUE_SANITIZE "" CACHE STRING "Sanitizers for every target (e.g. address,undefined); empty: none")
if(TISSUE_SANITIZE)
  add_compile_options(-fsanitize=${TISSUE_SANITIZE} -fno-sanitize-recover=all -fno-omit-frame-pointer -g1)
  add_link_options(-fsanitize=${TISSUE_SANITIZE})
endif()
