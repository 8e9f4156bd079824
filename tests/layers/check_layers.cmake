# check_layers.cmake -- every #include of the kernel goes down the layer order, or stays in
# its own folder.
#
#   cmake -DKERNEL=<kernel dir> -DORDER=<README.md> -DALLOW=<allowed list> -P check_layers.cmake
#
# The order is written once: the fenced block after the line containing
# "layer order (bottom first)" in README.md, one layer per line, bottom first; several
# folders on one line are peers (neither may include the other). A file's layer is the
# first folder of its path under kernel/; files directly in kernel/ (grassfire_version.h)
# are below every layer. An include "a/..." from a file in folder f is accepted when a is
# f, or a is on a lower line than f. Every other include is a violation unless the line
# "<file> -> <included path>" is in ALLOW (with its reason after a '#'). A folder of kernel/
# holding .h or .cpp files but missing from the order, and an include of a folder that is
# not in it, are violations too, and so is an installed header including a header that is not
# installed (*_detail.h, boost_*.h: see install() in CMakeLists.txt). Exits with an error
# listing every violation.
cmake_policy(VERSION 3.18)
foreach(var KERNEL ORDER ALLOW)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "check_layers.cmake: -D${var}=... is required")
  endif()
endforeach()

# The order, from README.md.
file(STRINGS "${ORDER}" readme)
set(state before)
set(rank 0)
foreach(line IN LISTS readme)
  if(state STREQUAL before AND line MATCHES "layer order \\(bottom first\\)")
    set(state marker)
  elseif(state STREQUAL marker AND line MATCHES "^```")
    set(state inside)
  elseif(state STREQUAL inside)
    if(line MATCHES "^```")
      set(state done)
      break()
    endif()
    string(REGEX REPLACE "#.*" "" line "${line}")
    string(REGEX MATCHALL "[A-Za-z0-9_]+" folders "${line}")
    if(folders)
      foreach(f IN LISTS folders)
        set(rank_${f} ${rank})
        list(APPEND layers ${f})
      endforeach()
      math(EXPR rank "${rank} + 1")
    endif()
  endif()
endforeach()
if(NOT state STREQUAL done OR NOT layers)
  message(FATAL_ERROR "check_layers.cmake: no layer order block (a line with \"layer order (bottom first)\" "
          "followed by a ``` block) in ${ORDER}")
endif()

# The allowed exceptions.
set(allowed "")
if(EXISTS "${ALLOW}")
  file(STRINGS "${ALLOW}" allow_lines)
  foreach(line IN LISTS allow_lines)
    string(REGEX REPLACE "#.*" "" line "${line}")
    string(STRIP "${line}" line)
    if(line)
      string(REGEX REPLACE "[ \t]*->[ \t]*" "->" line "${line}")
      list(APPEND allowed "${line}")
    endif()
  endforeach()
endif()

set(violations "")
set(used_allowances "")
file(GLOB_RECURSE sources RELATIVE "${KERNEL}" "${KERNEL}/*.h" "${KERNEL}/*.cpp")
list(SORT sources)
foreach(src IN LISTS sources)
  if(NOT src MATCHES "/")
    continue()  # kernel/grassfire_version.h: below every layer
  endif()
  string(REGEX REPLACE "/.*" "" from "${src}")
  if(NOT DEFINED rank_${from})
    list(APPEND violations "${src}: the folder kernel/${from}/ is in no layer of the order")
    continue()
  endif()
  file(STRINGS "${KERNEL}/${src}" includes REGEX "^[ \t]*#[ \t]*include[ \t]*\"[^\"]+\"")
  foreach(inc IN LISTS includes)
    string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*\"([^\"]+)\".*" "\\1" path "${inc}")
    if(NOT path MATCHES "/")
      continue()  # a file of the same folder, or kernel/grassfire_version.h
    endif()
    string(REGEX REPLACE "/.*" "" to "${path}")
    # A header that is installed must not include one that is not (CMakeLists.txt, install).
    get_filename_component(target_name "${path}" NAME)
    get_filename_component(src_name "${src}" NAME)
    if(src MATCHES "\\.h$" AND NOT src_name MATCHES "(_detail\\.h|^boost_.*\\.h)$"
       AND target_name MATCHES "(_detail\\.h|^boost_.*\\.h)$")
      list(APPEND violations "${src} -> ${path}: an installed header includes one that is not installed")
    endif()
    if(to STREQUAL from)
      continue()
    endif()
    if(NOT DEFINED rank_${to})
      set(problem "includes a folder that is in no layer")
    elseif(rank_${to} GREATER_EQUAL rank_${from})
      if(rank_${to} EQUAL rank_${from})
        set(problem "includes a peer layer (${from} and ${to} are on one line)")
      else()
        set(problem "goes up: ${to} is above ${from}")
      endif()
    else()
      continue()
    endif()
    if("${src}->${path}" IN_LIST allowed)
      list(APPEND used_allowances "${src}->${path}")
      continue()
    endif()
    list(APPEND violations "${src} -> ${path}: ${problem}")
  endforeach()
endforeach()

# An allowance that nothing uses any more is stale: it would hide the next violation there.
foreach(a IN LISTS allowed)
  if(NOT a IN_LIST used_allowances)
    list(APPEND violations "${ALLOW}: '${a}' allows an include that no longer exists: remove the line")
  endif()
endforeach()

list(LENGTH sources nfiles)
list(LENGTH layers nlayers)
if(violations)
  list(LENGTH violations n)
  string(REPLACE ";" "\n  " text "${violations}")
  message(FATAL_ERROR "check_layers: ${n} violation(s) of the layer order of ${ORDER}:\n  ${text}")
endif()
list(LENGTH used_allowances nallowed)
message(STATUS "check_layers: ${nfiles} files in ${nlayers} folders, every include goes down the order "
        "(${nallowed} listed exceptions)")
