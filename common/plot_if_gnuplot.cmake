# Draws a trade table with gnuplot when gnuplot is installed at the time of the build (not only at
# configure time): the trade and bench targets plot whenever they can, and say so when they cannot.
#   cmake -D SCRIPT=plot.gnuplot -D "ARGS=-e|csv='...'|-e|png='...'" -P plot_if_gnuplot.cmake
find_program(GNUPLOT gnuplot NO_CACHE)
if(NOT GNUPLOT)
  message(STATUS "gnuplot is not installed: the table is written, not drawn (apt-get install gnuplot-nox)")
  return()
endif()
string(REPLACE "|" ";" args "${ARGS}")
execute_process(COMMAND "${GNUPLOT}" ${args} "${SCRIPT}" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "gnuplot could not draw ${SCRIPT}")
endif()
