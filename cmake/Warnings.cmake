# skyig_warnings: an interface target every skyig target links, so the warning set is one list.
add_library(skyig_warnings INTERFACE)
target_compile_options(skyig_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion
  -Wnon-virtual-dtor -Wold-style-cast -Woverloaded-virtual
  -Wdouble-promotion -Wformat=2 -Wimplicit-fallthrough)
if(SKYIG_WERROR)
  target_compile_options(skyig_warnings INTERFACE -Werror)
endif()
# Not -Wnull-dereference: GCC 12 raises it at -O2 inside libstdc++'s std::string as inlined
# into CLI11, a false positive we cannot fix at our end.
