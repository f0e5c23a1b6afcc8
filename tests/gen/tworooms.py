#!/usr/bin/env python3
"""tworooms.py - the adversarial two-room grid of doorsure.h, doorlook.h and
thinwall.h (paper 2.3 task (i); issue 13 item 3): a 40 x 30 TABLE, one wall across
(horizontal at rows 10/18/21 or vertical at columns 12/20/26), 1-3 thick, a door 3-6
wide at three places, Utak at two starts and four headings, the four corners: 1728
worlds, 6912 runs. Not part of make check (hours on this machine); the false
successes those headers quote were counted on a sample of 4320 of its runs.

usage: python3 tests/gen/tworooms.py DIR > KEEP
Writes the worlds into DIR and, on stdout, one line per run in tests/rates.sh's keep
form (MODE|TASK|EXIT|LAST LINE|WORLD), verdicts blank, for a driver to run
`utak -q --max-cycles 300 WORLD TASK` on each."""
import os
import sys

def main():
    if len(sys.argv) != 2:
        sys.exit("usage: tworooms.py DIR")
    d = sys.argv[1]
    os.makedirs(d, exist_ok=True)
    for orient in 'hv':
        rows = (10, 18, 21) if orient == 'h' else (12, 20, 26)
        places = (5, 15, 29) if orient == 'h' else (4, 12, 21)
        starts = ((15.5, 7.5), (30.5, 5.5)) if orient == 'h' else ((5.5, 15.5), (8.5, 24.5))
        for r in rows:
            for th in (1, 2, 3):
                for dw in (3, 4, 5, 6):
                    for x0 in places:
                        if orient == 'h': # the wall from the west edge to the door, and from the door to the east edge
                            walls = 'wall 1 %d %d %d %d %d 1 %d\nwall %d %d 39 %d 39 %d %d %d\n' % (
                                r, x0, r, x0, r + th, r + th, x0 + dw, r, r, r + th, x0 + dw, r + th)
                        else: # from the south edge to the door, and from the door to the north edge
                            walls = 'wall %d 1 %d 1 %d %d %d %d\nwall %d %d %d %d %d 29 %d 29\n' % (
                                r, r + th, r + th, x0, r, x0, r, x0 + dw, r + th, x0 + dw, r + th, r)
                        for si, (ux, uy) in enumerate(starts):
                            for h in ('north', 'east', 'south', 'west'):
                                name = '%s%d-t%d-d%d-x%d-s%d-%s' % (orient, r, th, dw, x0, si, h)
                                p = os.path.join(d, name + '.w')
                                with open(p, 'w') as f:
                                    f.write('table 40 30\n' + walls + 'utak %.1f %.1f %s\n' % (ux, uy, h))
                                for c in ('ne', 'nw', 'se', 'sw'):
                                    print('grid|go %s-corner|0||%s' % (c, p))

if __name__ == '__main__':
    main()
