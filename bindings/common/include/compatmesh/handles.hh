// The C core's objects as C++ owners, and its progress callback as a C++
// callable: shared by the OpenMesh adapter, the Python module and the
// MeshLab plugin.
#pragma once

#include <exception>
#include <functional>
#include <memory>
#include <utility>

#include "compatmesh/compatmesh.h"

namespace compatmesh {

struct ResultDeleter {
  void operator()(cm_result *result) const { cm_result_free(result); }
};
struct MorphDeleter {
  void operator()(cm_morph *morph) const { cm_morph_free(morph); }
};
struct SweepDeleter {
  void operator()(cm_sweep *sweep) const { cm_sweep_free(sweep); }
};
using ResultPtr = std::unique_ptr<cm_result, ResultDeleter>;
using MorphPtr = std::unique_ptr<cm_morph, MorphDeleter>;
using SweepPtr = std::unique_ptr<cm_sweep, SweepDeleter>;

// Progress: fraction in [0, 1] and a short stage name; return true to cancel.
using ProgressFn = std::function<bool(double fraction, const char *stage)>;

// Carries a ProgressFn through the core's C callback. An exception must not
// cross the C code: what the function throws is kept, the run is cancelled,
// and rethrow() raises it once the core has returned.
class ProgressRelay {
 public:
  explicit ProgressRelay(ProgressFn fn) : fn_(std::move(fn)) {}
  ProgressRelay(const ProgressRelay &) = delete;
  ProgressRelay &operator=(const ProgressRelay &) = delete;

  // Points options (cm_options, cm_morph_options, cm_sweep_options) at
  // this relay when there is a function to call.
  template <class Options>
  void attach(Options &options)
  {
    if (fn_) {
      options.progress = &ProgressRelay::call;
      options.progress_user = this;
    }
  }

  void rethrow() const
  {
    if (error_) std::rethrow_exception(error_);
  }

 private:
  static int call(void *user, double fraction, const char *stage)
  {
    auto *self = static_cast<ProgressRelay *>(user);
    try {
      return self->fn_(fraction, stage) ? 1 : 0;
    } catch (...) {
      self->error_ = std::current_exception();
      return 1;
    }
  }

  ProgressFn fn_;
  std::exception_ptr error_;
};

}  // namespace compatmesh
