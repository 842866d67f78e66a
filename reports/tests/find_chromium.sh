# Sourced by the headless-Chromium checks (check_images_load.sh,
# check_svgs_render.sh): sets $chromium to the browser's path, or exits 77
# (a ctest skip, never a pass) when none is installed.
chromium=""
for candidate in chromium chromium-browser; do
  if command -v "$candidate" >/dev/null; then chromium=$(command -v "$candidate"); break; fi
done
if [ -z "$chromium" ]; then
  echo "NotSupported: chromium not installed (apt-get install chromium; scripts/setup.sh installs it)"
  exit 77
fi
