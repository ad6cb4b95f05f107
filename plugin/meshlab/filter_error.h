// What the workers throw: a one-line message the filter shows as its error.
#ifndef FILTER_COMPATMESH_FILTER_ERROR_H
#define FILTER_COMPATMESH_FILTER_ERROR_H

#include <stdexcept>

namespace compatmesh_plugin {

class FilterError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace compatmesh_plugin

#endif
