// Every std430 block the host fills or reads is laid out in C++ exactly as GLSL lays it out: each
// field's offset and each array's stride, queried from the linked production programs
// (program interface queries, OpenGL 4.5 core §7.3.1). A field counts as checked only where a
// program uses it (unused fields are not active), so every field must be active in some program.
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/camera_geometry.h"
#include "gpu/program.h"
#include "shaders/shared/gbuffer_kernel.h"
#include "shaders/shared/lighting.h"
#include "shaders/shared/lpv/lpv_types.h"
#include "shaders/shared/svo/build_kernel.h"
#include "shaders/shared/vct/compose_kernel.h"
#include "shaders/shared/vct/cone_types.h"
#include "shaders/shared/vct/light_voxels_kernel.h"
#include "shaders/shared/voxelize_layout.h"
#include "tests/gl_contexts.h"

namespace voxgi::test {
namespace {

using namespace shared;

// Every program the GPU stages link (gpu/*.cpp, gpu/vct/*.cpp, gpu/lpv/*.cpp, gpu/svo/*.cpp).
std::vector<std::vector<const ShaderSource*>> stagePrograms() {
  using namespace shaders;
  return {{&voxelize_vert, &voxelize_geom, &voxelize_frag},
          {&voxelize_antialiased_comp},
          {&voxelize_resolve_comp},
          {&gbuffer_vert, &gbuffer_frag},
          {&vct_light_voxels_comp},
          {&vct_mip_comp},
          {&vct_bounce_comp},
          {&vct_trace_cones_comp},
          {&vct_compose_comp},
          {&lpv_rsm_vert, &lpv_rsm_frag},
          {&lpv_inject_comp},
          {&lpv_inject_geometry_comp},
          {&lpv_inject_geometry_rsm_comp},
          {&lpv_propagate_comp},
          {&lpv_shade_comp},
          {&svo_build_comp},
          {&svo_propagate_inject_comp},
          {&svo_mip_comp},
          {&svo_propagate_gather_comp},
          {&gbuffer_disc_vert, &gbuffer_disc_frag},
          {&svo_mip_brick_comp},
          {&svo_shade_comp}};
}

struct Field {
  const char* name;
  size_t offset;  // offsetof in the C++ struct
};
#define VOXGI_FIELD(type, member)   \
  Field {                           \
#member, offsetof(type, member) \
  }

// A struct as a block member: `variable` is its GLSL name ("params", or "lights[0]" for an array
// whose first element starts at `base` bytes into the block and strides sizeof(type)).
struct Use {
  size_t program;  // index into stagePrograms()
  std::string variable;
  size_t base;
  bool array;
};

struct Layout {
  const char* type;
  size_t size;
  std::vector<Field> fields;
  std::vector<Use> uses;
};

std::vector<Layout> layouts() {
  enum {
    kVoxelize,
    kAntialiased,
    kResolve,
    kGbuffer,
    kLight,
    kMip,
    kBounce,
    kTrace,
    kCompose,
    kRsm,
    kInjectLpv,
    kInjectGeometry,
    kInjectGeometryRsm,
    kPropagate,
    kShadeLpv,
    kBuildSvo,
    kInjectSvo,
    kMipSvo,
    kGatherSvo,
    kGbufferDisc,
    kBrickSvo,
    kShadeSvo
  };
  return {
      {"VoxelTriangle",
       sizeof(VoxelTriangle),
       {VOXGI_FIELD(VoxelTriangle, v0), VOXGI_FIELD(VoxelTriangle, v1),
        VOXGI_FIELD(VoxelTriangle, v2), VOXGI_FIELD(VoxelTriangle, albedo),
        VOXGI_FIELD(VoxelTriangle, normal), VOXGI_FIELD(VoxelTriangle, emission),
        VOXGI_FIELD(VoxelTriangle, info)},
       {{kAntialiased, "triangles[0]", 0, true},
        {kVoxelize, "triangles[0]", 0, true},
        {kResolve, "triangles[0]", 0, true}}},
      {"SurfaceTriangle",
       sizeof(SurfaceTriangle),
       {VOXGI_FIELD(SurfaceTriangle, normal), VOXGI_FIELD(SurfaceTriangle, info)},
       {{kGbuffer, "triangles[0]", 0, true}, {kRsm, "triangles[0]", 0, true}}},
      {"SurfaceDisc",
       sizeof(SurfaceDisc),
       {VOXGI_FIELD(SurfaceDisc, center), VOXGI_FIELD(SurfaceDisc, normal),
        VOXGI_FIELD(SurfaceDisc, albedo), VOXGI_FIELD(SurfaceDisc, info)},
       {{kGbufferDisc, "discs[0]", 0, true}}},
      {"MaterialData",
       sizeof(MaterialData),
       {VOXGI_FIELD(MaterialData, albedo), VOXGI_FIELD(MaterialData, specular),
        VOXGI_FIELD(MaterialData, emission)},
       {{kGbuffer, "materials[0]", 0, true}, {kGbufferDisc, "materials[0]", 0, true}}},
      {"LightData",
       sizeof(LightData),
       {VOXGI_FIELD(LightData, position), VOXGI_FIELD(LightData, direction),
        VOXGI_FIELD(LightData, intensity), VOXGI_FIELD(LightData, falloff),
        VOXGI_FIELD(LightData, info)},
       {{kLight, "lights[0]", sizeof(LightVoxelsParams), true},
        {kTrace, "lights[0]", sizeof(ConeTraceParams), true},
        {kRsm, "lights[0]", 0, true},
        {kShadeLpv, "lights[0]", 0, true},
        {kInjectSvo, "lights[0]", sizeof(LightVoxelsParams), true},
        {kShadeSvo, "lights[0]", sizeof(ConeTraceParams), true}}},
      {"LightVoxelsParams",
       sizeof(LightVoxelsParams),
       {VOXGI_FIELD(LightVoxelsParams, config), VOXGI_FIELD(LightVoxelsParams, values)},
       {{kLight, "params", 0, false}, {kInjectSvo, "params", 0, false}}},
      {"ConeTraceParams",
       sizeof(ConeTraceParams),
       {VOXGI_FIELD(ConeTraceParams, grid), VOXGI_FIELD(ConeTraceParams, modes),
        VOXGI_FIELD(ConeTraceParams, limits), VOXGI_FIELD(ConeTraceParams, march),
        VOXGI_FIELD(ConeTraceParams, shadow), VOXGI_FIELD(ConeTraceParams, specular),
        VOXGI_FIELD(ConeTraceParams, background), VOXGI_FIELD(ConeTraceParams, camera),
        VOXGI_FIELD(ConeTraceParams, surface)},
       {{kTrace, "params", 0, false},
        {kBounce, "params", 0, false},
        {kGatherSvo, "params", 0, false},
        {kShadeSvo, "params", 0, false}}},
      {"ConeData",
       sizeof(ConeData),
       {VOXGI_FIELD(ConeData, direction), VOXGI_FIELD(ConeData, weight)},
       {{kTrace, "cones[0]", 0, true},
        {kBounce, "cones[0]", sizeof(ConeTraceParams), true},
        {kGatherSvo, "cones[0]", sizeof(ConeTraceParams), true}}},
      {"ObjectData",
       sizeof(ObjectData),
       {VOXGI_FIELD(ObjectData, specular)},
       {{kTrace, "objects[0]", 0, true}, {kShadeSvo, "objects[0]", 0, true}}},
      {"PixelTerms",
       sizeof(PixelTerms),
       {VOXGI_FIELD(PixelTerms, directDiffuse), VOXGI_FIELD(PixelTerms, directSpecular),
        VOXGI_FIELD(PixelTerms, indirectDiffuse), VOXGI_FIELD(PixelTerms, indirectSpecular),
        VOXGI_FIELD(PixelTerms, ambientOcclusion)},
       {{kTrace, "terms[0]", 0, true}}},
      {"ComposeInput",
       sizeof(ComposeInput),
       {VOXGI_FIELD(ComposeInput, albedo), VOXGI_FIELD(ComposeInput, specular),
        VOXGI_FIELD(ComposeInput, emission), VOXGI_FIELD(ComposeInput, directDiffuse),
        VOXGI_FIELD(ComposeInput, directSpecular), VOXGI_FIELD(ComposeInput, indirectDiffuse),
        VOXGI_FIELD(ComposeInput, indirectSpecular), VOXGI_FIELD(ComposeInput, ambientOcclusion)},
       {{kCompose, "inputs[0]", 0, true}}},
      {"Vpl",
       sizeof(Vpl),
       {VOXGI_FIELD(Vpl, position), VOXGI_FIELD(Vpl, normal), VOXGI_FIELD(Vpl, flux)},
       {{kInjectLpv, "vpls[0]", sizeof(InjectParams), true}}},
      {"InjectParams",
       sizeof(InjectParams),
       {VOXGI_FIELD(InjectParams, shape), VOXGI_FIELD(InjectParams, scale)},
       {{kInjectLpv, "params", 0, false}}},
      {"PropagationEntry",
       sizeof(PropagationEntry),
       {VOXGI_FIELD(PropagationEntry, offset),
        {"sampled[0]", offsetof(PropagationEntry, sampled)},
        {"reprojected[0]", offsetof(PropagationEntry, reprojected)},
        {"blocking[0]", offsetof(PropagationEntry, blocking)}},
       {{kPropagate, "entries[0]", sizeof(PropagateParams), true}}},
      {"PropagateParams",
       sizeof(PropagateParams),
       {VOXGI_FIELD(PropagateParams, shape), VOXGI_FIELD(PropagateParams, options),
        VOXGI_FIELD(PropagateParams, storage)},
       {{kPropagate, "params", 0, false}}},
      {"ShadeParams",
       sizeof(ShadeParams),
       {VOXGI_FIELD(ShadeParams, shape), VOXGI_FIELD(ShadeParams, scale),
        VOXGI_FIELD(ShadeParams, camera)},
       {{kShadeLpv, "params", 0, false}}},
      {"RsmView",
       sizeof(RsmView),
       {VOXGI_FIELD(RsmView, origin), VOXGI_FIELD(RsmView, forward), VOXGI_FIELD(RsmView, right),
        VOXGI_FIELD(RsmView, up), VOXGI_FIELD(RsmView, info)},
       {{kRsm, "views[0]", sizeof(RsmParams), true},
        {kInjectLpv, "views[0]", sizeof(RsmParams), true},
        {kShadeLpv, "views[0]", sizeof(RsmParams), true},
        {kInjectGeometryRsm, "views[0]", sizeof(RsmParams), true}}},
      {"SvoSample",
       sizeof(SvoSample),
       {VOXGI_FIELD(SvoSample, position), VOXGI_FIELD(SvoSample, albedo),
        VOXGI_FIELD(SvoSample, normal), VOXGI_FIELD(SvoSample, emission)},
       {{kBuildSvo, "samples[0]", 0, true}}},
      {"RsmParams",
       sizeof(RsmParams),
       {VOXGI_FIELD(RsmParams, shape), VOXGI_FIELD(RsmParams, scale)},
       {{kRsm, "params", 0, false},
        {kInjectLpv, "rsm", 0, false},
        {kShadeLpv, "rsm", 0, false},
        {kInjectGeometryRsm, "rsm", 0, false}}},
  };
}

TEST(Layout, EveryProgramLinksOnBothPlatforms) {
  for (gpu::GlPlatform p : {gpu::GlPlatform::osmesa, gpu::GlPlatform::egl}) {
    gpu::GlContext& context = glContext(p);
    context.makeCurrent();
    for (const auto& stages : stagePrograms()) {
      const std::string name(stages.front()->name);
      EXPECT_NO_THROW(gpu::Program(context.gl(), stages)) << name;
    }
  }
  // ... and those are all of them: every embedded shader is in one.
  for (const ShaderSource* s : shaders::kAll) {
    bool used = false;
    for (const auto& stages : stagePrograms())
      for (const ShaderSource* t : stages) used |= t == s;
    EXPECT_TRUE(used) << s->name << " is embedded but in no program of the test";
  }
}

TEST(Layout, EveryHostSharedStd430BlockMatchesCpp) {
  gpu::GlContext& context = glContext(gpu::GlPlatform::egl);
  context.makeCurrent();
  const gpu::Gl& gl = context.gl();
  std::vector<std::unique_ptr<gpu::Program>> programs;
  for (const auto& stages : stagePrograms())
    programs.push_back(std::make_unique<gpu::Program>(gl, stages));
  // A buffer variable's property, or -1 where the program has no such active variable.
  auto query = [&](size_t program, const std::string& variable, GLenum property) {
    const GLuint id = programs[program]->id();
    const GLuint index = gl.GetProgramResourceIndex(id, GL_BUFFER_VARIABLE, variable.c_str());
    if (index == GL_INVALID_INDEX) return GLint(-1);
    GLint value = -1;
    gl.GetProgramResourceiv(id, GL_BUFFER_VARIABLE, index, 1, &property, 1, nullptr, &value);
    return value;
  };
  for (const Layout& layout : layouts()) {
    EXPECT_EQ(layout.size % 16, 0u) << layout.type << ": std430 rounds a struct of vec4s to 16";
    for (const Field& f : layout.fields) {
      bool active = false;
      for (const Use& use : layout.uses) {
        const std::string variable = use.variable + "." + f.name;
        const GLint offset = query(use.program, variable, GL_OFFSET);
        if (offset < 0) continue;
        active = true;
        EXPECT_EQ(size_t(offset), use.base + f.offset) << layout.type << " " << variable;
        if (use.array) {
          EXPECT_EQ(size_t(query(use.program, variable, GL_TOP_LEVEL_ARRAY_STRIDE)), layout.size)
              << layout.type << " " << variable;
        }
      }
      EXPECT_TRUE(active) << layout.type << "." << f.name << " is active in no program";
    }
  }
}

}  // namespace
}  // namespace voxgi::test
