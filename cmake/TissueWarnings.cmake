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
  if(TISSUE_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
