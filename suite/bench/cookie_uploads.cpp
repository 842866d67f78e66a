// Cookies' upload time apart from their sampling (SPEC 9, cookies on and
// off): prepareTextures() of a fresh prepared scene of the cookie
// field (FieldSpec::cookies: a tiled directional, two projected spot and two
// cube cookies), at several cookie sizes. The frame modes `cookies` and
// `cookie-lights` (field_modes.cpp) time the draws without it.
#include "suite/bench/bench_families.h"
#include "suite/bench/bench_scenes.h"

#include <string>
#include <vector>

namespace bench {

std::vector<int> cookieUploadSizes(bool quick) {
  if (quick) return {256};  // --quick, and a slow driver (its share of the budget)
  return {64, 256, 1024};
}

void registerCookieUploads(Registrar& r) {
  const std::string scene = fieldSceneName(r.run());
  const FieldSize fieldSize = bench::fieldSize(r.run());
  for (const int size : cookieUploadSizes(r.run().settings.quick || r.run().slow())) {
    r.upload(scene, kCookiesMode, std::to_string(size), [scene, size, fieldSize] {
      FieldSpec field;
      field.width = fieldSize.width;
      field.height = fieldSize.height;
      field.cookies = true;
      field.cookieSize = size;
      const std::string name = scene + "-" + kCookiesMode + "-" + std::to_string(size);
      return lighting::prepareFrame(lighting::prepareScene(fieldScene(field, name)), 0);
    });
  }
}

}  // namespace bench
