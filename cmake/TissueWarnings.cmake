# tissue_set_warnings(target): the project's warning set; errors when TISSUE_WERROR is on.
function(tissue_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
                                           -Wold-style-cast -Wcast-align -Wunused -Woverloaded-virtual
                                           -Wdouble-promotion -Wformat=2 -Wimplicit-fallthrough)
  if(TISSUE_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
