#!/usr/bin/env bash
# Opens RUN_DIR/report/index.html in headless Chromium and checks that every
# <img> in it loaded and decoded (complete, naturalWidth > 0), and that there
# is at least one.
#
#   check_images_load.sh RUN_DIR
#
# The report has no JavaScript, so the check runs on a copy in a temporary
# folder with two additions: <base href> pointing at the real report folder
# (every relative path resolves exactly as in the original) and a small
# script that, after the load event, writes its findings into the page, which
# --dump-dom prints. The run folder is not written to.
#
# Exit: 0 every image loaded; 1 an image did not load, there is none, or the
# check could not run; 2 usage; 77 chromium is not installed (a skip).
set -euo pipefail

if [ $# -ne 1 ]; then
  echo "usage: $0 RUN_DIR" >&2
  exit 2
fi
report_dir=$(cd "$1" 2>/dev/null && pwd)/report || { echo "FAIL: no folder $1" >&2; exit 1; }
page="$report_dir/index.html"
[ -f "$page" ] || { echo "FAIL: no $page" >&2; exit 1; }

. "$(dirname "${BASH_SOURCE[0]}")/find_chromium.sh"

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# file:// URL of the report folder: bytes other than unreserved ones and "/"
# percent-encoded.
url_path() {
  local LC_ALL=C s="$1" out="" c h i
  for ((i = 0; i < ${#s}; i++)); do
    c=${s:i:1}
    case "$c" in
      [a-zA-Z0-9/._~-]) out+="$c" ;;
      *) printf -v h '%%%02X' "'$c"; out+="${h: -3}" ;;
    esac
  done
  printf '%s' "$out"
}
base_url="file://$(url_path "$report_dir/")"

checker='<script>
window.addEventListener("load", function () {
  var images = Array.prototype.slice.call(document.images);
  var failed = images.filter(function (i) { return !(i.complete && i.naturalWidth > 0); });
  var out = document.createElement("pre");
  out.textContent = "LIGHTCTS-" + "IMAGES total=" + images.length + " failed=" + failed.length + "\n" +
    failed.map(function (i) { return "NOT LOADED: " + i.getAttribute("src") + "\n"; }).join("") +
    "LIGHTCTS-" + "IMAGES-END";
  document.body.appendChild(out);
});
</script>'

# <base> must come before anything that uses a URL: right after <head>. The
# markers are split in the script so that only its output matches them. The
# texts go through the environment: awk -v would expand the script's "\n".
grep -qi '<head>' "$page" || { echo "FAIL: $page has no <head>" >&2; exit 1; }
BASE="<base href=\"$base_url\">" CHECKER="$checker" awk '
  !done_base && (at = index($0, "<head>")) {
    $0 = substr($0, 1, at + 5) "\n" ENVIRON["BASE"] substr($0, at + 6); done_base = 1 }
  !done_script && (at = index($0, "</body>")) {
    $0 = substr($0, 1, at - 1) ENVIRON["CHECKER"] "\n" substr($0, at); done_script = 1 }
  { print }' "$page" > "$work/check.html"

started=$(date +%s%N)
set +e
timeout 90 "$chromium" --headless --no-sandbox --disable-gpu --disable-dev-shm-usage --no-first-run --no-default-browser-check \
  --user-data-dir="$work/profile" --virtual-time-budget=5000 --dump-dom "file://$work/check.html" \
  > "$work/dom.html" 2> "$work/chromium.log"
status=$?
set -e
elapsed_ms=$(( ($(date +%s%N) - started) / 1000000 ))

result=$(sed -n '/LIGHTCTS-IMAGES total=[0-9]/,/LIGHTCTS-IMAGES-END/p' "$work/dom.html" | sed 's/<[^>]*>//g')
if [ -z "$result" ]; then
  echo "FAIL: chromium (exit $status) did not report on the images of $page" >&2
  tail -20 "$work/chromium.log" >&2
  exit 1
fi
echo "$result"
total=$(echo "$result" | sed -n 's/.*total=\([0-9]*\).*/\1/p' | head -1)
failed=$(echo "$result" | sed -n 's/.*failed=\([0-9]*\).*/\1/p' | head -1)
in_source=$(grep -o '<img[ >]' "$page" | wc -l)
echo "chromium: ${elapsed_ms} ms; <img> tags in the page: $in_source"
if [ "$total" != "$in_source" ]; then
  echo "FAIL: the page has $in_source <img> tags but chromium saw $total" >&2
  exit 1
fi
if [ "$total" -eq 0 ]; then
  echo "FAIL: $page shows no images" >&2
  exit 1
fi
if [ "$failed" -ne 0 ]; then
  echo "FAIL: $failed of $total images in $page did not load" >&2
  exit 1
fi
echo "PASS: all $total images in $page loaded"
