#!/usr/bin/env bash
# Regenerates the example textures with OpenImageIO's oiiotool (the committed
# PNGs are its output; rerun after changing a line here and update the goldens).
set -euo pipefail
cd "$(dirname "$0")"

# An 8 x 8 checker with a red 16 x 16 block at the image's bottom-left, so that
# a flipped or transposed uv shows in a render.
oiiotool --pattern checker:width=8:height=8:color1=0.9,0.85,0.7:color2=0.25,0.3,0.45 64x64 3 \
  --fill:color=0.8,0.1,0.1 16x16+0+48 -d uint8 -o checker.png

# White with alpha rising from 0.3 (left) to 0.8 (right): the transparent
# materials' coverage.
oiiotool --pattern fill:left=1,1,1,0.3:right=1,1,1,0.8 32x32 4 -d uint8 -o glass.png

# A tangent-space normal map of tiles tilted alternately left and right
# (linear data: load it with "srgb": false).
oiiotool --pattern checker:width=8:height=8:color1=0.75,0.5,0.93:color2=0.25,0.5,0.93 32x32 3 -d uint8 -o tiles_normal.png

# A light cookie (grey: the cookie's alpha is its grey level): a window of four
# panes with a dark square in the top-left pane's corner, so that a flipped or
# rotated projection shows; softened by a blur.
oiiotool --pattern constant:color=0 64x64 1 --fill:color=1 23x23+6+6 --fill:color=1 23x23+35+6 \
  --fill:color=1 23x23+6+35 --fill:color=1 23x23+35+35 --fill:color=0 9x9+6+6 --blur 3x3 -d uint8 -o cookie_window.png

# A directional light's cookie: a soft checker of light and shade (tiles every
# cookie_size world units).
oiiotool --pattern checker:width=16:height=16:color1=1:color2=0.2 64x64 1 --blur 7x7 -d uint8 -o cookie_checker.png

# An HDR studio environment (equirectangular, linear half floats, row 0
# looking up): a sky gradient over a warm ground, a small sun (radiance 60)
# up and to the left behind a camera looking along +Z, and two soft boxes low
# in front, so that smooth spheres show sharp highlights and rough ones a
# blur of them.
oiiotool --pattern constant:color=0 256x128 3 \
  --fill:top=0.25,0.4,0.8:bottom=0.8,0.85,0.9 256x64+0+0 --fill:top=0.25,0.22,0.18:bottom=0.1,0.08,0.06 256x64+0+64 \
  --fill:color=6,5.6,5 24x12+24+46 --fill:color=4,4.4,5 24x12+104+46 \
  --blur 3x3 --fill:color=60,56,50 5x5+216+37 -d half -o studio.exr
