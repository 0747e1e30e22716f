# Strict warnings for FooBall's own targets only; third-party headers come in as SYSTEM.
function(fooball_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                           -Wno-sign-conversion -Wnon-virtual-dtor)
  if(FOOBALL_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
