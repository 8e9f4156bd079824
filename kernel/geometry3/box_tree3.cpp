// box_tree3.cpp -- see box_tree3.h.
#include "geometry3/box_tree3.h"

#include <algorithm>
#include <numeric>

namespace grassfire {
namespace {

BoxTree3::Box hull_of(const std::vector<BoxTree3::Box>& boxes, const std::uint32_t* begin, const std::uint32_t* end) {
  BoxTree3::Box box = boxes[*begin];
  for (const std::uint32_t* i = begin; i != end; ++i)
    for (int k = 0; k < 3; ++k) box[k] = hull(box[k], boxes[*i][k]);
  return box;
}

// The longest axis of a box (an axis of infinite extent counts as longest).
int longest_axis(const BoxTree3::Box& box) {
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (!(box[k].hi - box[k].lo <= box[axis].hi - box[axis].lo)) axis = k;
  return axis;
}

// The centre of an extent as a sort key (0 for an extent infinite both ways: never NaN,
// which would break the strict weak order of the median split).
double centre(const Interval& x) {
  const double c = 0.5 * x.lo + 0.5 * x.hi;
  return c == c ? c : 0.0;
}

}  // namespace

BoxTree3::BoxTree3(const std::vector<Box>& boxes) : items_(boxes.size()) {
  if (boxes.empty()) return;
  std::iota(items_.begin(), items_.end(), 0u);
  nodes_.reserve(2 * (boxes.size() / kLeafSize + 1));
  Node root;
  root.end = static_cast<std::uint32_t>(boxes.size());
  root.box = hull_of(boxes, items_.data(), items_.data() + items_.size());
  nodes_.push_back(root);
  // Nodes are split in creation order; each split appends two children, so the loop ends
  // after at most 2 n / kLeafSize + 1 nodes.
  for (std::uint32_t n = 0; n < nodes_.size(); ++n) split(n, boxes);
}

void BoxTree3::split(std::uint32_t n, const std::vector<Box>& boxes) {
  const std::uint32_t begin = nodes_[n].begin, end = nodes_[n].end;
  if (end - begin <= kLeafSize) return;
  const int axis = longest_axis(nodes_[n].box);
  const std::uint32_t mid = begin + (end - begin) / 2;
  std::nth_element(items_.begin() + begin, items_.begin() + mid, items_.begin() + end,
                   [&](std::uint32_t a, std::uint32_t b) {
                     return centre(boxes[a][axis]) < centre(boxes[b][axis]);
                   });
  Node left, right;
  left.begin = begin, left.end = mid, right.begin = mid, right.end = end;
  left.box = hull_of(boxes, items_.data() + begin, items_.data() + mid);
  right.box = hull_of(boxes, items_.data() + mid, items_.data() + end);
  nodes_[n].left = static_cast<std::uint32_t>(nodes_.size());
  nodes_.push_back(left);
  nodes_.push_back(right);
}

}  // namespace grassfire
