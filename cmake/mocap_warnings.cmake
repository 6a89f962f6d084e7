# mocap_enable_warnings(<target>): the project's warning set, -Werror when MOCAP_WERROR is on.
function(mocap_enable_warnings target)
  target_compile_options(${target} PRIVATE
    -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wsign-conversion -Wnon-virtual-dtor
    -Wold-style-cast -Woverloaded-virtual -Wnull-dereference -Wdouble-promotion -Wformat=2)
  if(MOCAP_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
