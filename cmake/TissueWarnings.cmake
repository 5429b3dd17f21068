# tissue_set_warnings(target): the project's warning set; errors when TISSUE_WERROR is on.
function(tissue_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
                                           -Wold-style-cast -Wcast-align -Wunused -Woverloaded-virtual
                                           -Wdouble-promotion -Wformat=2 -Wimplicit-fallthrough)
  if(TISSUE_SANITIZE AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    # GCC's manual: with -fsanitize=address, -Wmaybe-uninitialized reports false positives (seen
    # in OpenMesh's Property.hh); the unsanitized trees keep the warning.
    target_compile_options(${target} PRIVATE -Wno-maybe-uninitialized)
  endif()
  if(CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    # Clang's -Wdouble-promotion flags every float-to-double initialisation, the explicit
    # double{f} included (the widening the geometry code does on purpose before a difference);
    # GCC's flags the implicit promotions in float arithmetic the warning is meant to catch, and
    # the GCC trees keep it (docs/DECISIONS.md, "The sanitized tree is built by clang").
    target_compile_options(${target} PRIVATE -Wno-double-promotion)
  endif()
  if(TISSUE_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
