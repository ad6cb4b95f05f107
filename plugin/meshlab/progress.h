// The core's progress callback forwarded to MeshLab's vcg::CallBackPos a
// few times a second (each call repaints MeshLab's progress bar).
#ifndef FILTER_COMPATMESH_PROGRESS_H
#define FILTER_COMPATMESH_PROGRESS_H

#include <vcg/space/point3.h>
#include <wrap/callback.h>

#include <compatmesh/openmesh.hh>

#include <chrono>
#include <string>

namespace compatmesh_plugin {

class ThrottledProgress {
 public:
  explicit ThrottledProgress(vcg::CallBackPos *cb) : cb_(cb) {}
  // Reports fraction (0..1) of the part [begin, end] of the whole run.
  void report(double fraction, const char *stage, double begin = 0, double end = 1)
  {
    if (!cb_) return;
    auto now = std::chrono::steady_clock::now();
    if (reported_ && now - last_ < std::chrono::milliseconds(250) && fraction < 1) return;
    reported_ = true;
    last_ = now;
    cb_(int(100 * (begin + fraction * (end - begin))), stage);
  }
  compatmesh::ProgressFn as_function(double begin = 0, double end = 1)
  {
    return [this, begin, end](double fraction, const char *stage) {
      report(fraction, stage, begin, end);
      return false;  // MeshLab's callbacks cannot cancel
    };
  }

 private:
  vcg::CallBackPos *cb_;
  bool reported_ = false;
  std::chrono::steady_clock::time_point last_;
};

}  // namespace compatmesh_plugin

#endif
