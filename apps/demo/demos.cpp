#include "demos.h"

#include "demo_support.h"

namespace pathlab::demo {

const std::vector<Demo>& allDemos() {
  static const std::vector<Demo> demos = {pdfCdfDemo(), discreteDemo(),          annulusDemo(),     hemisphereDemo(),
                                          piDemo(),     renderingEquationDemo(), environmentDemo(), sequencesDemo()};
  return demos;
}

}  // namespace pathlab::demo
