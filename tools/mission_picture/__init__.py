"""The picture of a finished run (tools/render_mission.py), one module per part it draws:

  run_log   the inputs (through tools/mission_files)    picture   the SVG document
  objects   the field's objects and the report rings     cues      detections, classifications
  tracks    tracks, swath coverage, vehicle ends         scale     scale bar, north arrow
  panel     score table and summary lines                legend    the legend
  rows      panel rows                                   output    SVG and PNG files
  layout    sizes and styles                             colours   colour words, vehicle colours
  geometry  view, markers, track reduction              detail    the level of detail
  text_fit  text widths and fitting
"""
