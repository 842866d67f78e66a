#include "reports/svg_labels.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace reports::svg {
namespace {

// Points closer than this (pixels, each axis) are one spot: their markers
// overlap, and one label serves them all.
constexpr double kSameSpot = 6;
// Clear space kept between a label and anything else.
constexpr double kGap = 1.5;
// A joined group label longer than this becomes prefix-and-count.
constexpr std::size_t kLongestJoined = 40;

bool overlaps(const LabelBox& a, const LabelBox& b) {
  return a.x0 < b.x1 + kGap && b.x0 < a.x1 + kGap && a.y0 < b.y1 + kGap && b.y0 < a.y1 + kGap;
}

bool inside(const LabelBox& box, const LabelBox& frame) {
  return box.x0 >= frame.x0 + kGap && box.x1 <= frame.x1 - kGap && box.y0 >= frame.y0 + kGap &&
         box.y1 <= frame.y1 - kGap;
}

double textWidth(const std::string& text) {
  // UTF-8: count code points, not bytes.
  std::size_t glyphs = 0;
  for (unsigned char c : text) glyphs += (c & 0xC0) != 0x80;
  return kLabelCharWidth * double(glyphs);
}

struct Group {
  std::vector<std::size_t> members;  // indices into the requests, in order
  bool front = false;
  double x0, y0, x1, y1;  // the members' points' extent
};

// Single-link grouping of the points within kSameSpot of each other.
std::vector<Group> groupsOf(const std::vector<LabelRequest>& requests) {
  std::vector<std::size_t> parent(requests.size());
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  const auto root = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (std::size_t i = 0; i < requests.size(); ++i)
    for (std::size_t j = i + 1; j < requests.size(); ++j)
      if (std::abs(requests[i].px - requests[j].px) < kSameSpot && std::abs(requests[i].py - requests[j].py) < kSameSpot)
        parent[root(j)] = root(i);
  std::vector<Group> groups;
  std::vector<std::size_t> groupOfRoot(requests.size(), requests.size());
  for (std::size_t i = 0; i < requests.size(); ++i) {
    const std::size_t r = root(i);
    if (groupOfRoot[r] == requests.size()) {
      groupOfRoot[r] = groups.size();
      groups.push_back({{}, false, requests[i].px, requests[i].py, requests[i].px, requests[i].py});
    }
    Group& g = groups[groupOfRoot[r]];
    g.members.push_back(i);
    g.front = g.front || requests[i].front;
    g.x0 = std::min(g.x0, requests[i].px), g.x1 = std::max(g.x1, requests[i].px);
    g.y0 = std::min(g.y0, requests[i].py), g.y1 = std::max(g.y1, requests[i].py);
  }
  // The front first; otherwise in the order the points came.
  std::stable_sort(groups.begin(), groups.end(), [](const Group& a, const Group& b) { return a.front && !b.front; });
  return groups;
}

// The places tried for a label of width w beside a group, nearest first:
// right, left, above, below and the four diagonals, then the same directions
// further out (a leader line joins those to the point).
std::vector<LabelBox> candidates(const Group& g, double w) {
  const double h = kLabelHeight, cx = (g.x0 + g.x1) / 2, cy = (g.y0 + g.y1) / 2;
  std::vector<LabelBox> out;
  for (int ring = 0; ring < 12; ++ring) {
    const double d = 11 + 13 * ring;  // beyond the marker (and its front ring), then a line further each ring
    const LabelBox places[] = {
        {g.x1 + d, cy - h / 2, g.x1 + d + w, cy + h / 2},          // right
        {g.x0 - d - w, cy - h / 2, g.x0 - d, cy + h / 2},          // left
        {cx - w / 2, g.y0 - d - h, cx + w / 2, g.y0 - d},          // above
        {cx - w / 2, g.y1 + d, cx + w / 2, g.y1 + d + h},          // below
        {g.x1 + d * 0.7, g.y0 - d * 0.7 - h, g.x1 + d * 0.7 + w, g.y0 - d * 0.7},  // above right
        {g.x1 + d * 0.7, g.y1 + d * 0.7, g.x1 + d * 0.7 + w, g.y1 + d * 0.7 + h},  // below right
        {g.x0 - d * 0.7 - w, g.y0 - d * 0.7 - h, g.x0 - d * 0.7, g.y0 - d * 0.7},  // above left
        {g.x0 - d * 0.7 - w, g.y1 + d * 0.7, g.x0 - d * 0.7, g.y1 + d * 0.7 + h},  // below left
        {g.x1 + 4, g.y0 - d - h, g.x1 + 4 + w, g.y0 - d},          // above, starting at the point
        {g.x1 + 4, g.y1 + d, g.x1 + 4 + w, g.y1 + d + h},          // below, starting at the point
        {g.x0 - 4 - w, g.y0 - d - h, g.x0 - 4, g.y0 - d},          // above, ending at the point
        {g.x0 - 4 - w, g.y1 + d, g.x0 - 4, g.y1 + d + h},          // below, ending at the point
    };
    out.insert(out.end(), std::begin(places), std::end(places));
  }
  return out;
}

std::string commonPrefix(const std::vector<std::string>& labels) {
  std::string prefix = labels.front();
  for (const std::string& l : labels) {
    std::size_t n = 0;
    while (n < prefix.size() && n < l.size() && prefix[n] == l[n]) ++n;
    prefix.resize(n);
  }
  // At a word boundary: "shadows-bilinear-256" and "shadows-hard-1024" share "shadows-".
  const std::size_t cut = prefix.find_last_of("-_/ ");
  return cut == std::string::npos ? std::string() : prefix.substr(0, cut + 1);
}

}  // namespace

std::string groupLabel(const std::vector<std::string>& labels) {
  if (labels.empty()) return "";
  std::vector<std::string> distinct;
  for (const std::string& l : labels)
    if (std::find(distinct.begin(), distinct.end(), l) == distinct.end()) distinct.push_back(l);
  if (distinct.size() == 1) return labels.size() == 1 ? distinct.front() : distinct.front() + " (" + std::to_string(labels.size()) + ")";
  std::string joined;
  for (const std::string& l : distinct) joined += (joined.empty() ? "" : ", ") + l;
  if (joined.size() <= kLongestJoined) return joined;
  const std::string prefix = commonPrefix(distinct);
  if (prefix.size() >= 3) return prefix + "* (" + std::to_string(labels.size()) + ")";
  return distinct.front() + " +" + std::to_string(labels.size() - 1) + " more";
}

std::vector<PlacedLabel> placeLabels(const std::vector<LabelRequest>& requests, const std::vector<LabelBox>& markers,
                                     const LabelBox& frame) {
  std::vector<LabelBox> taken = markers;
  std::vector<PlacedLabel> placed;
  for (const Group& g : groupsOf(requests)) {
    std::vector<std::string> texts;
    std::string title;
    for (std::size_t i : g.members) {
      texts.push_back(requests[i].text);
      title += (title.empty() ? "" : "\n") + (requests[i].title.empty() ? requests[i].text : requests[i].title);
    }
    const std::string text = groupLabel(texts);
    const double w = textWidth(text);
    const std::vector<LabelBox> places = candidates(g, w);
    for (std::size_t k = 0; k < places.size(); ++k) {
      const LabelBox& box = places[k];
      if (!inside(box, frame) ||
          std::any_of(taken.begin(), taken.end(), [&](const LabelBox& t) { return overlaps(box, t); }))
        continue;
      taken.push_back(box);
      const LabelRequest& first = requests[g.members.front()];
      // The first twelve places touch the group; the rest need a line to it.
      placed.push_back({text, title, g.front, k >= 12, first.px, first.py, box});
      break;
    }
  }
  return placed;
}

}  // namespace reports::svg
