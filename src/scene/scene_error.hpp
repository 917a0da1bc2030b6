#pragma once
// The exception the scene layer throws for what it cannot do with its inputs: a font FreeType
// cannot read, a picture that cannot be encoded or written. The message says what and why.

#include <stdexcept>

namespace trailray::scene {

class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace trailray::scene
