# Sourced by the window tests (POSIX sh): shot NAME writes the screen of the Xvfb display as
# $out/NAME.png and $tmp/NAME.ppm, with the open menus pasted over it, since in a grab of the
# root window alone they are black. Needs xdotool and netpbm; windows narrower than the
# 1280-pixel screen are taken as popups.
shot() {
  xwd -root -silent | xwdtopnm 2> /dev/null > "$tmp/screen.ppm"
  for w in $(xdotool search --maxdepth 1 --onlyvisible --name ""); do
    eval "$(xdotool getwindowgeometry --shell "$w")"
    [ "$WIDTH" -lt 1280 ] || continue
    xwd -id "$w" -silent | xwdtopnm 2> /dev/null > "$tmp/popup.ppm"
    pnmpaste "$tmp/popup.ppm" "$X" "$Y" "$tmp/screen.ppm" > "$tmp/pasted.ppm" 2> /dev/null
    mv "$tmp/pasted.ppm" "$tmp/screen.ppm"
  done
  pnmtopng "$tmp/screen.ppm" > "$out/$1.png" 2> /dev/null
  cp "$tmp/screen.ppm" "$tmp/$1.ppm"
}
