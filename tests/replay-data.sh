#!/bin/sh
# replay-data.sh - the data of a replay page (utak --html): the lines inside its
# <script id="utak-replay-data"> element, that is the page less the fixed viewer.
#
#   sh tests/replay-data.sh PAGE.html
sed -n '/^<script id="utak-replay-data"/,/^<\/script>/p' "$1" | sed '1d;$d'
