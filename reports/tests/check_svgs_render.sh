#!/usr/bin/env bash
# Opens every DIR/*.html (the benchmark pages, docs/bench-report.md) in
# headless Chromium and checks that every inline <svg> plot renders: a
# non-zero bounding box (getBBox) and layout box, and drawn elements (paths,
# lines, circles, text) of non-zero extent; that no point label overlaps
# another label or a point (their getBBox boxes, as the browser laid them
# out); and that the pages have at least one <svg> between them. The
# browser runs with every network access failing (file:// only).
#
#   check_svgs_render.sh DIR
#
# One Chromium for all the pages: a driver page in a temporary folder loads
# each page, unchanged, in an 800x600 iframe (headless Chromium's window
# size) and, after each load event, checks its plots through the frame's
# document (--allow-file-access-from-files lets a file:// page read another's);
# it writes its findings into itself, which --dump-dom prints. DIR is not
# written to.
#
# Exit: 0 every plot rendered; 1 a plot did not, there is none, or the check
# could not run; 2 usage; 77 chromium is not installed (a skip).
set -euo pipefail

if [ $# -ne 1 ]; then
  echo "usage: $0 DIR" >&2
  exit 2
fi
dir=$(cd "$1" 2>/dev/null && pwd) || { echo "FAIL: no folder $1" >&2; exit 1; }
shopt -s nullglob
pages=("$dir"/*.html)
[ ${#pages[@]} -gt 0 ] || { echo "FAIL: no .html files in $dir" >&2; exit 1; }

. "$(dirname "${BASH_SOURCE[0]}")/find_chromium.sh"

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The pages' URLs, as a JavaScript array (file names are the report's own:
# letters, digits, '.', '-' and '_').
urls=""
for page in "${pages[@]}"; do
  name=$(basename "$page")
  case "$name" in *[!A-Za-z0-9._-]*) echo "FAIL: unexpected page name $name" >&2; exit 1 ;; esac
  urls="$urls\"file://$dir/$name\","
done

# The markers are split in the script so that only its output matches them.
cat > "$work/check.html" <<EOF
<!DOCTYPE html><html><body>
<script>
var urls = [${urls%,}];
var lines = new Array(urls.length), pending = urls.length;
function check(doc) {
  var svgs = Array.prototype.slice.call(doc.querySelectorAll("svg"));
  var broken = [], labelCount = 0;
  svgs.forEach(function (s, i) {
    var why = [];
    var box = s.getBBox(), rect = s.getBoundingClientRect();
    if (!(box.width > 0 && box.height > 0)) why.push("empty bounding box " + box.width + "x" + box.height);
    if (!(rect.width > 0 && rect.height > 0)) why.push("no layout box " + rect.width + "x" + rect.height);
    var shapes = Array.prototype.slice.call(s.querySelectorAll("path, line, polyline, polygon, circle, ellipse, text"));
    var drawn = shapes.filter(function (e) { var b = e.getBBox(); return b.width > 0 || b.height > 0; });
    if (drawn.length === 0) why.push("nothing drawn (" + shapes.length + " shapes, all empty)");
    // Point labels (reports/svg_labels.h): none over another label or over a point.
    var labels = Array.prototype.slice.call(s.querySelectorAll("g.labels text"));
    var points = Array.prototype.slice.call(s.querySelectorAll("circle.pt, circle.ring"));
    var lb = labels.map(function (t) { return t.getBBox(); });
    var pb = points.map(function (c) { return c.getBBox(); });
    var hit = function (a, b) { return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height; };
    var text = function (t) { return (t.lastChild && t.lastChild.nodeType === 3 ? t.lastChild : t).textContent; };
    var overlaps = [];
    for (var a = 0; a < lb.length; ++a) {
      for (var b = a + 1; b < lb.length; ++b)
        if (hit(lb[a], lb[b])) overlaps.push("label '" + text(labels[a]) + "' over label '" + text(labels[b]) + "'");
      for (var p = 0; p < pb.length; ++p)
        if (hit(lb[a], pb[p]))
          overlaps.push("label '" + text(labels[a]) + "' over point '" + (points[p].getAttribute("data-point") || "ring") + "'");
    }
    if (overlaps.length) why.push(overlaps.length + " overlaps: " + overlaps.slice(0, 5).join("; "));
    labelCount += labels.length;
    if (why.length) broken.push("BROKEN SVG #" + i + " \"" + (s.getAttribute("aria-label") || "") + "\": " + why.join("; "));
  });
  return "labels=" + labelCount + " total=" + svgs.length + " broken=" + broken.length + "\n" +
         broken.map(function (b) { return b + "\n"; }).join("");
}
function finish() {
  var out = document.createElement("pre");
  out.textContent = "LIGHTCTS-" + "SVGS\n" + lines.join("") + "LIGHTCTS-" + "SVGS-END";
  document.body.appendChild(out);
}
urls.forEach(function (url, k) {
  var frame = document.createElement("iframe");
  frame.style.width = "800px";
  frame.style.height = "600px";
  frame.addEventListener("load", function () {
    var name = url.substring(url.lastIndexOf("/") + 1);
    try {
      lines[k] = "PAGE " + name + " " + check(frame.contentDocument);
    } catch (e) {
      lines[k] = "PAGE " + name + " unreadable: " + e + "\n";
    }
    if (--pending === 0) finish();
  });
  frame.src = url;
  document.body.appendChild(frame);
});
</script>
</body></html>
EOF

started=$(date +%s%N)
set +e
# With every network access failing: the pages must work from file:// alone.
timeout 90 "$chromium" --headless --no-sandbox --disable-gpu --disable-dev-shm-usage --no-first-run \
  --no-default-browser-check --user-data-dir="$work/profile" --allow-file-access-from-files \
  --proxy-server=127.0.0.1:9 --host-resolver-rules='MAP * ~NOTFOUND' \
  --virtual-time-budget=5000 --dump-dom "file://$work/check.html" > "$work/dom.html" 2> "$work/chromium.log"
status=$?
set -e
result=$(sed -n '/LIGHTCTS-SVGS$/,/LIGHTCTS-SVGS-END/p' "$work/dom.html" | sed 's/<[^>]*>//g')
if [ -z "$result" ]; then
  echo "FAIL: chromium (exit $status) did not report on the plots of $dir" >&2
  tail -20 "$work/chromium.log" >&2
  exit 1
fi

all_total=0
all_broken=0
failed=0
for page in "${pages[@]}"; do
  name=$(basename "$page")
  line=$(echo "$result" | grep "^PAGE $name " || true)
  if [ -z "$line" ] || ! echo "$line" | grep -q ' total=[0-9]* broken=[0-9]*$'; then
    echo "FAIL: chromium did not report on the plots of $name: $line" >&2
    failed=1
    continue
  fi
  total=$(echo "$line" | sed -n 's/.* total=\([0-9]*\).*/\1/p')
  broken=$(echo "$line" | sed -n 's/.* broken=\([0-9]*\).*/\1/p')
  labels=$(echo "$line" | sed -n 's/.* labels=\([0-9]*\) .*/\1/p')
  in_source=$( (grep -o '<svg[ >]' "$page" || true) | wc -l)
  echo "$name: $total plots, $broken broken, ${labels:-0} point labels"
  echo "$result" | awk -v page="PAGE $name " 'index($0, page) == 1 { on = 1; next } /^PAGE / { on = 0 } on && /^BROKEN SVG/'
  if [ "$total" != "$in_source" ]; then
    echo "FAIL: $name has $in_source <svg> tags but chromium saw $total" >&2
    failed=1
  fi
  all_total=$((all_total + total))
  all_broken=$((all_broken + broken))
done
elapsed_ms=$(( ($(date +%s%N) - started) / 1000000 ))
echo "chromium: ${elapsed_ms} ms for ${#pages[@]} pages"
if [ "$all_total" -eq 0 ]; then
  echo "FAIL: no <svg> in the pages of $dir" >&2
  exit 1
fi
if [ "$all_broken" -ne 0 ] || [ "$failed" -ne 0 ]; then
  echo "FAIL: $all_broken of $all_total plots in $dir did not render, or have overlapping labels" >&2
  exit 1
fi
echo "PASS: all $all_total plots in ${#pages[@]} pages of $dir rendered"
