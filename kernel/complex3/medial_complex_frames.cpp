// medial_complex_frames.cpp -- the exact planar frames of a MedialComplex, computed when
// first asked for (see medial_complex.h), and their part of validate().
//
// A frame costs some 50 rational operations; a curved sheet of a mesh has one per
// triangle, so computing them all at construction cost more than everything else together,
// for data that most users never read (the exact engine builds its own patch frames). The
// frame layout (which frame index each triangle uses, which triangle spans each frame) is
// fixed at construction; the frames themselves are computed here, each at most once.
#include <mutex>
#include <stdexcept>

#include "complex3/medial_complex.h"

namespace grassfire {

std::array<mpq_class, 2> PlanarFrame::local(const ExactPoint3& p) const {
  const ExactPoint3 d = p - origin;
  return {mpq_class(dot(d, e1) / e1_norm2), mpq_class(dot(d, e2) / e2_norm2)};
}

bool PlanarFrame::contains(const ExactPoint3& p) const { return sgn(dot(normal, p - origin)) == 0; }

PlanarFrame frame_of_triangle(const ExactPoint3& a, const ExactPoint3& b, const ExactPoint3& c) {
  PlanarFrame f;
  f.origin = a;
  f.e1 = b - a;
  f.e2 = cross(cross(b - a, c - a), f.e1);
  f.normal = cross(f.e1, f.e2);
  f.e1_norm2 = dot(f.e1, f.e1);
  f.e2_norm2 = dot(f.e2, f.e2);
  return f;
}

// Shared by copies of a MedialComplex (they have the same vertices and layout).
struct MedialComplex::FrameStore {
  std::mutex mutex;
  std::vector<std::unique_ptr<PlanarFrame>> computed;  // by frame index; stable addresses
  std::vector<PlanarFrame> all;                        // filled by frames()
  bool all_ready = false;
};

std::shared_ptr<MedialComplex::FrameStore> MedialComplex::make_frame_store(std::size_t frames) {
  auto store = std::make_shared<FrameStore>();
  store->computed.resize(frames);
  return store;
}

const PlanarFrame& MedialComplex::frame(std::uint32_t f) const {
  FrameStore& store = *frame_store_;
  const std::lock_guard<std::mutex> lock(store.mutex);
  if (store.all_ready) return store.all[f];
  std::unique_ptr<PlanarFrame>& slot = store.computed[f];
  if (!slot) {
    const auto& tv = triangles_[frame_triangle_[f]].v;
    slot = std::make_unique<PlanarFrame>(
        frame_of_triangle(vertices_[tv[0]].exact, vertices_[tv[1]].exact, vertices_[tv[2]].exact));
  }
  return *slot;
}

const PlanarFrame& MedialComplex::triangle_frame(std::uint32_t t) const { return frame(triangle_frame_[t]); }

const std::vector<PlanarFrame>& MedialComplex::frames() const {
  FrameStore& store = *frame_store_;
  const std::lock_guard<std::mutex> lock(store.mutex);
  if (store.all_ready) return store.all;
  store.all.reserve(frame_triangle_.size());
  for (std::uint32_t f = 0; f < frame_triangle_.size(); ++f) {
    if (store.computed[f]) {  // a copy: references handed out before stay valid
      store.all.push_back(*store.computed[f]);
      continue;
    }
    const auto& tv = triangles_[frame_triangle_[f]].v;
    store.all.push_back(frame_of_triangle(vertices_[tv[0]].exact, vertices_[tv[1]].exact, vertices_[tv[2]].exact));
  }
  store.all_ready = true;
  return store.all;
}

// The layout (a planar sheet's triangles share the frame its first triangle spans; every
// other triangle spans its own) and every frame computed so far, exactly: orthogonal axes,
// normal = e1 x e2, and the plane through its triangle's three vertices. A frame not yet
// computed is determined by the layout, which is checked.
void MedialComplex::validate_frames() const {
  const auto violation = [&](const std::string& what) {
    throw std::logic_error("MedialComplex " + source_ + " invalid: " + what);
  };
  if (triangle_frame_.size() != triangles_.size() || !frame_store_) violation("frame layout size");
  for (std::uint32_t s = 0; s < sheets_.size(); ++s) {
    const Sheet& sh = sheets_[s];
    for (std::uint32_t t : sh.triangles) {
      const std::uint32_t f = triangle_frame_[t];
      const std::uint32_t spanning = sh.planar ? sh.triangles.front() : t;
      if (f >= frame_triangle_.size() || frame_triangle_[f] != spanning || (sh.planar && f != sh.frame))
        violation("frame of triangle " + std::to_string(t) + " is not the one of its sheet's layout");
    }
    if (!sh.planar && sh.frame != kNoIndex) violation("curved sheet " + std::to_string(s) + " has a frame");
  }
  FrameStore& store = *frame_store_;
  const std::lock_guard<std::mutex> lock(store.mutex);
  for (std::uint32_t f = 0; f < frame_triangle_.size(); ++f) {
    const PlanarFrame* fr = store.all_ready ? &store.all[f] : store.computed[f].get();
    if (!fr) continue;
    if (sgn(dot(fr->e1, fr->e2)) != 0 || !(fr->normal == cross(fr->e1, fr->e2)) ||
        fr->e1_norm2 != dot(fr->e1, fr->e1) || fr->e2_norm2 != dot(fr->e2, fr->e2))
      violation("frame " + std::to_string(f) + " is not orthogonal");
    for (std::uint32_t v : triangles_[frame_triangle_[f]].v)
      if (!fr->contains(vertices_[v].exact)) violation("frame " + std::to_string(f) + " misses its triangle");
    if (is_zero(fr->normal)) violation("frame " + std::to_string(f) + " is degenerate");
  }
}

}  // namespace grassfire
