# The programs' allocator. Every program moves many short strings per cycle (a message's
# fields, a node report's text, an event line), and glibc's malloc spends a third of the dense
# field's sensor cycle on them; mimalloc (Debian's libmimalloc-dev) serves the same requests in
# far fewer instructions and keeps freed blocks per thread (docs/performance.md, "The
# allocator"). Only the programs link it: the engine library a user embeds keeps the allocator
# of the user's program.
#
# The sanitizer builds keep the sanitizers' own allocator, which finds the errors they test for.
if(HAZARD_SANITIZE OR HAZARD_TSAN OR HAZARD_FUZZ)
  set(HAZARD_MIMALLOC OFF CACHE BOOL "" FORCE)
endif()
if(HAZARD_MIMALLOC)
  find_package(mimalloc 2.0 CONFIG)
  if(NOT mimalloc_FOUND)
    message(FATAL_ERROR "HAZARD_MIMALLOC needs libmimalloc-dev (./build.sh deps installs it), "
                        "or configure with -DHAZARD_MIMALLOC=OFF for glibc's allocator")
  endif()
endif()

# hazard_use_allocator(<target>): <target> allocates through mimalloc when HAZARD_MIMALLOC is
# on. The library is linked even where the linker's --as-needed would drop it: a program whose
# own code calls no malloc still allocates through libstdc++, which finds malloc in the first
# library that defines it, and mimalloc comes before the C library.
function(hazard_use_allocator target)
  if(HAZARD_MIMALLOC)
    target_link_libraries(${target} PRIVATE "-Wl,--push-state,--no-as-needed" mimalloc
                          "-Wl,--pop-state")
  endif()
endfunction()
