"""Reading the files a mission run leaves behind, for every Python tool of the project, and
writing the files a user names.

  text         the base text grammar (include/base/text.hpp): numbers, booleans, trimming,
               `key=value` lists, point lists, as the C++ programs read them
  alog         the .alog written by pLogLite (include/moos/alog.hpp)
  hazard_file  hazard files, the ground truth (docs/hazard-file.md, src/hazard/hazard_field.cpp)
  run_files    what the launcher writes beside the log: summary.json and cpu.txt
  output_file  writing a user-named output (summary.json, the picture): a regular file replaced
               atomically, a device or FIFO written through, a link kept, a folder refused
               (the rule of include/base/output_file.hpp)

The one rule every reader shares is the C++ number grammar: `nan`, `inf` and `1e999` are not
numbers anywhere (a field holding one is treated as missing or rejected, as the C++ readers do).
Python 3 standard library only. The missions' summary (missions/common/mission_summary.py) and
the picture (tools/render_mission.py) read their inputs and write their outputs through this
package and nothing else.
"""
