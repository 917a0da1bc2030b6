# Warnings for project code only (third-party headers come in as SYSTEM).
function(trailray_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
    -Wno-sign-conversion)
  if(TRAILRAY_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
