# lesson_tables_refresh's second half: each chapter's trade plot, drawn by the `trade` target into
# TRADE_DIR/NN_name.png, copied beside its lesson as chapters/NN_name/trade.png (the image the
# lesson's "The trade" section shows). Without gnuplot there is no plot to copy: the lesson keeps
# the image it has, and the refresh says so.
#   cmake -D TRADE_DIR=build/trade -D KIT=<kit> -D CHAPTERS=01_ray_casting,02_spheres_triangles,... -P lesson_plots.cmake
string(REPLACE "," ";" chapters "${CHAPTERS}")
foreach(chapter IN LISTS chapters)
  set(plot "${TRADE_DIR}/${chapter}.png")
  if(EXISTS "${plot}")
    file(COPY_FILE "${plot}" "${KIT}/chapters/${chapter}/trade.png" ONLY_IF_DIFFERENT)
  else()
    message(WARNING "${plot} was not drawn (gnuplot not installed?): chapters/${chapter}/trade.png kept as it was")
  endif()
endforeach()
