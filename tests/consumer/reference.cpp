// Path traces a scene with the installed reference renderer alone (voxgi::reference: no GL).
#include <iostream>

#include <voxgi/common/scene_io/scene_load.h>
#include <voxgi/validation/reference/path_trace.h>

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  voxgi::Scene scene = voxgi::loadScene(argv[1]);
  scene.camera.width = scene.camera.height = 16;
  voxgi::reference::PathTraceOptions options;
  options.spp = 1;
  const voxgi::reference::PathTraceResult r = voxgi::reference::pathTrace(scene, options);
  double sum = 0.0;
  for (const auto& p : r.image.pixels) sum += double(p.x + p.y + p.z);
  std::cout << "reference consumer: mean radiance " << sum / double(r.image.pixels.size() * 3)
            << "\n";
  return sum > 0.0 ? 0 : 1;
}
