// Textures: the sRGB table against IEC 61966-2-1's values, wrap modes, bilinear and mip filtering
// of shaders/shared/texture_kernel.h against values worked out by hand, the PNG and JPEG readers
// on good and bad files, and textures reaching materials from OBJ/MTL and glTF.
#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <turbojpeg.h>
#include <zlib.h>

#include "common/error.h"
#include "common/io/image_io.h"
#include "common/io/texture_read.h"
#include "common/scene_io/scene_load.h"
#include "common/texture.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

using shared::kWrapClamp;
using shared::kWrapMirror;
using shared::kWrapRepeat;

DecodedImage imageOf(int w, int h, const std::vector<uint8_t>& grey) {
  DecodedImage image{w, h, {}};
  for (uint8_t g : grey) image.rgb.insert(image.rgb.end(), {g, g, g});
  return image;
}

// The texture of `image` under the name "<width>x<height>": one image per size.
uint32_t addTexture(TexturePool& pool, const DecodedImage& image, uint32_t wrapS = kWrapRepeat,
                    uint32_t wrapT = kWrapRepeat) {
  return pool.texture(std::to_string(image.width) + "x" + std::to_string(image.height), wrapS,
                      wrapT, [&] { return image; });
}

float sampleRed(const TexturePool& pool, uint32_t t, glm::vec2 uv, float lod) {
  return shared::sampleTexture(TextureAccess{pool}, pool.textures[t], uv, lod).x;
}

TEST(Texture, SrgbTableHasTheStandardsValuesAndEncodingInvertsIt) {
  const std::array<float, 256>& t = srgbDecodeTable();
  EXPECT_EQ(t[0], 0.0f);
  EXPECT_EQ(t[255], 1.0f);
  // The linear segment (code / 255 / 12.92) and the power segment, from the formula by hand.
  EXPECT_NEAR(t[10], 10.0 / 255.0 / 12.92, 1e-9);
  EXPECT_NEAR(t[128], 0.2158605, 1e-6);
  EXPECT_NEAR(t[188], 0.5028865, 1e-6);
  for (uint32_t c = 0; c < 256; ++c) {
    ASSERT_EQ(srgbEncode(t[c]), c);
    if (c > 0) {
      ASSERT_GT(t[c], t[c - 1]);
    }
  }
  EXPECT_EQ(srgbEncode(-1.0f), 0u);
  EXPECT_EQ(srgbEncode(2.0f), 255u);
  EXPECT_EQ(srgbEncode(0.5f), 188u);  // t[187] = 0.4969, t[188] = 0.5029
}

TEST(Texture, WrapModesFoldTexelIndices) {
  // Repeat: period n; clamp: the edge texels; mirror: period 2n, reflected.
  EXPECT_EQ(shared::wrapTexel(-1, 4, kWrapRepeat), 3);
  EXPECT_EQ(shared::wrapTexel(9, 4, kWrapRepeat), 1);
  EXPECT_EQ(shared::wrapTexel(-1, 4, kWrapClamp), 0);
  EXPECT_EQ(shared::wrapTexel(7, 4, kWrapClamp), 3);
  EXPECT_EQ(shared::wrapTexel(-1, 4, kWrapMirror), 0);
  EXPECT_EQ(shared::wrapTexel(4, 4, kWrapMirror), 3);
  EXPECT_EQ(shared::wrapTexel(5, 4, kWrapMirror), 2);
  EXPECT_EQ(shared::wrapTexel(8, 4, kWrapMirror), 0);
  // Coordinates far outside [0, 1] wrap without overflowing an int.
  EXPECT_EQ(shared::wrapCoordinate(1e6f + 0.25f, kWrapRepeat), 0.25f);
  EXPECT_EQ(shared::wrapCoordinate(-0.25f, kWrapRepeat), 0.75f);
  EXPECT_EQ(shared::wrapCoordinate(-0.25f, kWrapMirror), 1.75f);
  EXPECT_EQ(shared::wrapCoordinate(-3.0f, kWrapClamp), 0.0f);
}

TEST(Texture, BilinearFilteringBlendsLinearValuesAndWraps) {
  TexturePool pool;
  // Black then white: texel centres at u = 1/4 and 3/4.
  const DecodedImage image = imageOf(2, 1, {0, 255});
  const uint32_t repeat = addTexture(pool, image);
  const uint32_t clamp = addTexture(pool, image, kWrapClamp, kWrapClamp);
  const uint32_t mirror = addTexture(pool, image, kWrapMirror, kWrapMirror);
  EXPECT_EQ(pool.texels.size(), 3u);  // one image (2 texels and its 1x1 level), three samplers
  EXPECT_EQ(sampleRed(pool, repeat, {0.25f, 0.5f}, 0.0f), 0.0f);
  EXPECT_EQ(sampleRed(pool, repeat, {0.75f, 0.5f}, 0.0f), 1.0f);
  // Halfway between the centres: half of the linear values (not of the sRGB codes).
  EXPECT_EQ(sampleRed(pool, repeat, {0.5f, 0.5f}, 0.0f), 0.5f);
  EXPECT_EQ(sampleRed(pool, repeat, {0.375f, 0.5f}, 0.0f), 0.25f);
  // At u = 0: repeat blends the last texel in; clamp reads the first; mirror reflects it.
  EXPECT_EQ(sampleRed(pool, repeat, {0.0f, 0.5f}, 0.0f), 0.5f);
  EXPECT_EQ(sampleRed(pool, clamp, {0.0f, 0.5f}, 0.0f), 0.0f);
  EXPECT_EQ(sampleRed(pool, mirror, {0.0f, 0.5f}, 0.0f), 0.0f);
  EXPECT_EQ(sampleRed(pool, mirror, {1.25f, 0.5f}, 0.0f), 1.0f);  // mirrored: white at 1 + 1/4
}

TEST(Texture, MipLevelsAverageInLinearSpaceAndTheLodFollowsTheFootprint) {
  TexturePool pool;
  std::vector<uint8_t> checker;
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) checker.push_back((x + y) % 2 ? 255 : 0);
  const uint32_t t = addTexture(pool, imageOf(8, 8, checker));
  const shared::TextureRecord& r = pool.textures[t];
  EXPECT_EQ(r.levels, 4);
  EXPECT_EQ(pool.texels.size(), 64u + 16u + 4u + 1u);
  // Every texel of level 1 and below is the linear mean 1/2, stored as its nearest code 188.
  for (size_t i = 64; i < pool.texels.size(); ++i) ASSERT_EQ(pool.texels[i] & 255u, 188u);
  // A footprint of one texel magnifies (level 0); of the whole texture, its 1x1 level.
  EXPECT_EQ(shared::textureLod(r, 1.0f / 8.0f), 0.0f);
  EXPECT_EQ(shared::textureLod(r, 0.5f), 2.0f);
  EXPECT_EQ(shared::textureLod(r, 1.0f), 3.0f);
  EXPECT_EQ(shared::textureLod(r, 100.0f), 3.0f);
  EXPECT_EQ(shared::textureLod(r, 0.0f), 0.0f);
  EXPECT_EQ(sampleRed(pool, t, {0.3f, 0.7f}, 1.0f), srgbDecodeTable()[188]);
  // Between levels 0 and 1 at a black texel's centre: linear between 0 and the grey.
  EXPECT_FLOAT_EQ(sampleRed(pool, t, {1.0f / 16.0f, 1.0f / 16.0f}, 0.5f),
                  0.5f * srgbDecodeTable()[188]);
}

TEST(Texture, AConstantTextureIsItsValueBitForBit) {
  TexturePool pool;
  const uint32_t grey = addTexture(pool, imageOf(5, 3, std::vector<uint8_t>(15, 77)));
  const uint32_t white = addTexture(pool, imageOf(4, 4, std::vector<uint8_t>(16, 255)));
  const TextureAccess access{pool};
  const glm::vec3 factor(0.8f, 0.3f, 0.55f);
  for (float u : {-3.7f, 0.0f, 0.123f, 0.5f, 0.999f, 17.25f})
    for (float footprint : {0.0f, 0.01f, 0.3f, 1.0f, 5.0f}) {
      const glm::vec2 uv(u, 1.0f - u);
      ASSERT_EQ(shared::texturedValue(access, glm::vec3(1.0f), grey, uv, footprint),
                glm::vec3(srgbDecodeTable()[77]));
      // A white texture times a factor is the untextured material.
      ASSERT_EQ(shared::texturedValue(access, factor, white, uv, footprint), factor);
      ASSERT_EQ(shared::texturedValue(access, factor, shared::kNoTexture, uv, footprint), factor);
    }
}

std::string pngBytes(int w, int h, const std::vector<unsigned char>& rgb) {
  const std::string path = writeTemp("texture_png_source.png", "");
  writeRgb8Png(path, w, h, rgb);
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

std::string jpegBytes(int w, int h, const std::vector<unsigned char>& rgb) {
  tjhandle t = tjInitCompress();
  unsigned char* out = nullptr;
  unsigned long size = 0;
  EXPECT_EQ(tjCompress2(t, rgb.data(), w, 0, h, TJPF_RGB, &out, &size, TJSAMP_444, 100, 0), 0);
  std::string bytes(reinterpret_cast<char*>(out), size);
  tjFree(out);
  tjDestroy(t);
  return bytes;
}

TEST(TextureRead, PngAndJpegDecodeToTheirPixels) {
  std::vector<unsigned char> rgb;
  for (int i = 0; i < 16 * 8; ++i) rgb.insert(rgb.end(), {200, 100, 50});
  rgb[0] = 0;  // the first pixel of the first row: v = 0
  const DecodedImage png = decodeTexture(pngBytes(16, 8, rgb), "a.png", "");
  EXPECT_EQ(png.width, 16);
  EXPECT_EQ(png.height, 8);
  EXPECT_EQ(png.rgb, rgb);
  const DecodedImage jpeg = decodeTexture(jpegBytes(16, 8, rgb), "a.jpg", "");
  ASSERT_EQ(jpeg.width, 16);
  ASSERT_EQ(jpeg.height, 8);
  // Lossy at quality 100: each channel of a flat pixel far from the edited one within a few codes.
  const size_t far = (7 * 16 + 15) * 3;
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(jpeg.rgb[far + size_t(c)], rgb[far + size_t(c)], 3);
}

void expectRefused(const std::string& bytes, const std::string& message) {
  try {
    decodeTexture(bytes, "bad.img", "images[0]");
    ADD_FAILURE() << "accepted; expected " << message;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.img: images[0]: "), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
  }
}

TEST(TextureRead, BadImagesAreRefusedNamingTheFile) {
  const std::vector<unsigned char> rgb(32 * 32 * 3, 90);
  const std::string png = pngBytes(32, 32, rgb), jpeg = jpegBytes(32, 32, rgb);
  expectRefused(png.substr(0, png.size() / 2), "cannot read PNG");
  expectRefused(jpeg.substr(0, jpeg.size() / 2), "cannot read JPEG");
  expectRefused("GIF89a...", "not a PNG or JPEG image");
  expectRefused("", "not a PNG or JPEG image");
  // A PNG header declaring 100000 x 32 (its CRC made right): refused before any pixel is
  // allocated. IHDR's data starts at byte 16, its CRC covers "IHDR" and the 13 data bytes.
  std::string wide = png;
  const uint32_t width = 100000;
  for (int i = 0; i < 4; ++i) wide[size_t(16 + i)] = char((width >> (24 - 8 * i)) & 255u);
  const uLong crc = crc32(0, reinterpret_cast<const Bytef*>(wide.data() + 12), 17);
  for (int i = 0; i < 4; ++i) wide[size_t(29 + i)] = char((crc >> (24 - 8 * i)) & 255u);
  expectRefused(wide, "size 100000x32 is outside 1..16384");
  // A JPEG frame header declaring 60000 x 60000 rows and columns.
  std::string huge = jpeg;
  const size_t sof = huge.find("\xff\xc0");
  ASSERT_NE(sof, std::string::npos);
  for (size_t i : {sof + 5, sof + 7}) {
    huge[i] = char(60000 >> 8);
    huge[i + 1] = char(60000 & 255);
  }
  expectRefused(huge, "size 60000x60000 is outside 1..16384");
  try {
    readTexture("/nonexistent/wall.png", "model.obj", "material 'x' map_Kd");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find("model.obj: material 'x' map_Kd: /nonexistent/wall.png: "),
              0u)
        << e.what();
  }
}

// A unit square in z = 0 with texture coordinates, as OBJ + MTL + PNG files.
std::string texturedObj(const std::string& mtlExtra) {
  const std::string dir = std::filesystem::path(writeTemp("wall.obj", "")).parent_path();
  std::vector<unsigned char> rgb = {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255};
  writeRgb8Png(dir + "/wall.png", 2, 2, rgb);
  std::ofstream(dir + "/wall.mtl")
      << "newmtl wall\nKd 0.5 0.5 0.5\nmap_Kd " << mtlExtra << "wall.png\n";
  std::ofstream(dir + "/wall.obj") << "mtllib wall.mtl\nusemtl wall\n"
                                      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                      "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                                      "f 1/1 2/2 3/3\nf 1/1 3/3 4/4\n";
  return dir + "/wall.obj";
}

TEST(TextureScene, ObjMapKdBecomesTheAlbedoTextureWithFlippedV) {
  const Scene s = loadScene(texturedObj(""));
  ASSERT_EQ(s.textures.textures.size(), 1u);
  const Mesh& mesh = s.meshes.at(0);
  const Material& m = s.materials.at(mesh.material);
  EXPECT_EQ(m.albedoTexture, 0u);
  EXPECT_EQ(m.emissionTexture, shared::kNoTexture);
  EXPECT_EQ(s.textures.textures[0].wrapS, kWrapRepeat);
  ASSERT_EQ(mesh.texcoords.size(), mesh.positions.size());
  // OBJ's v = 0 is the image's last row: the vertex at (0, 0, 0) reads the bottom-left texel.
  for (size_t v = 0; v < mesh.positions.size(); ++v)
    if (mesh.positions[v] == glm::dvec3(0.0)) {
      EXPECT_EQ(mesh.texcoords[v], glm::vec2(0.0f, 1.0f));
    }
  const glm::vec3 bottomLeft = shared::texturedValue(TextureAccess{s.textures}, m.albedo,
                                                     m.albedoTexture, {0.25f, 0.75f}, 0.0f);
  EXPECT_EQ(bottomLeft, glm::vec3(0.0f, 0.0f, 0.5f));  // blue (row 1, column 0) times Kd
  // -clamp on: clamp to edge.
  const Scene clamped = loadScene(texturedObj("-clamp on "));
  EXPECT_EQ(clamped.textures.textures.at(0).wrapS, kWrapClamp);
}

TEST(TextureScene, MissingTextureFileIsRefusedNamingIt) {
  const std::string obj = texturedObj("");
  std::filesystem::remove(std::filesystem::path(obj).parent_path() / "wall.png");
  try {
    loadScene(obj);
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("wall.png"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("map_Kd"), std::string::npos) << e.what();
  }
}

// One triangle with TEXCOORD_0 (in a .bin beside it), its material's base colour and emission
// textured from a PNG file and from the same image under another sampler.
TEST(TextureScene, GltfTexturesAndSamplersReachTheMaterial) {
  const std::filesystem::path dir = std::filesystem::path(writeTemp("tri.gltf", "")).parent_path();
  const float data[15] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0.0f, 0.0f, 2.0f, 0.0f, 0.0f, 0.5f};
  std::ofstream(dir / "tri.bin", std::ios::binary)
      .write(reinterpret_cast<const char*>(data), sizeof data);
  writeRgb8Png((dir / "tex.png").string(), 1, 1, {255, 128, 0});
  std::ofstream(dir / "tri.gltf") << R"({"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],
    "nodes":[{"mesh":0}],
    "buffers":[{"byteLength":60,"uri":"tri.bin"}],
    "bufferViews":[{"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":24}],
    "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"},
                 {"bufferView":1,"componentType":5126,"count":3,"type":"VEC2"}],
    "images":[{"uri":"tex.png"}],
    "samplers":[{"wrapS":33071,"wrapT":33648}],
    "textures":[{"source":0},{"source":0,"sampler":0}],
    "materials":[{"pbrMetallicRoughness":{"baseColorFactor":[0.5,0.5,0.5,1],"metallicFactor":0,
                  "baseColorTexture":{"index":0}},
                  "emissiveFactor":[1,1,1],"emissiveTexture":{"index":1}}],
    "meshes":[{"primitives":[{"attributes":{"POSITION":0,"TEXCOORD_0":1},"material":0}]}]})";
  const Scene s = loadScene((dir / "tri.gltf").string());
  const Mesh& mesh = s.meshes.at(0);
  const Material& m = s.materials.at(mesh.material);
  ASSERT_EQ(s.textures.textures.size(), 2u);
  EXPECT_EQ(s.textures.texels.size(), 1u);  // one image, two samplers
  EXPECT_EQ(s.textures.textures[m.albedoTexture].wrapS, kWrapRepeat);
  EXPECT_EQ(s.textures.textures[m.emissionTexture].wrapS, kWrapClamp);
  EXPECT_EQ(s.textures.textures[m.emissionTexture].wrapT, kWrapMirror);
  EXPECT_EQ(mesh.texcoords, (std::vector<glm::vec2>{{0.0f, 0.0f}, {2.0f, 0.0f}, {0.0f, 0.5f}}));
  const glm::vec3 emission = shared::texturedValue(TextureAccess{s.textures}, m.emission,
                                                   m.emissionTexture, {0.3f, 0.3f}, 0.0f);
  EXPECT_EQ(emission, glm::vec3(1.0f, srgbDecodeTable()[128], 0.0f));
  // A texture coordinate set other than 0 is refused, naming the field.
  std::string text;
  {
    std::ifstream in(dir / "tri.gltf");
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  text.replace(text.find(R"("emissiveTexture":{"index":1})"), 29,
               R"("emissiveTexture":{"index":1,"texCoord":1})");
  std::ofstream(dir / "tri.gltf") << text;
  try {
    loadScene((dir / "tri.gltf").string());
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("materials[0].emissiveTexture.texCoord"),
              std::string::npos)
        << e.what();
  }
}

// The shipped textured Cornell box (scripts/textured_cornell_box): its JSON materials name the
// textures; a scene file's own material with a texture and a wrap mode; a bad wrap mode refused.
TEST(TextureScene, SceneFileMaterialsNameTexturesRelativeToTheFile) {
  const Scene box = loadScene(std::string(VOXGI_SOURCE_DIR) + "/scenes/cornell_box_textured.json");
  EXPECT_EQ(box.textures.textures.size(), 3u);  // tiles, bricks, grid
  size_t textured = 0;
  for (const Mesh& mesh : box.meshes) {
    const Material& m = box.materials[mesh.material];
    if (m.albedoTexture == shared::kNoTexture) continue;
    ++textured;
    EXPECT_EQ(mesh.texcoords.size(), mesh.positions.size()) << mesh.name;
    EXPECT_EQ(m.albedo, glm::vec3(1.0f));
  }
  EXPECT_EQ(textured, 12u);  // floor, back wall, the two blocks' 5 + 5 faces
  const std::string dir = std::filesystem::path(texturedObj("")).parent_path();
  const std::string scene = R"({"meshes":[{"file":"wall.obj"}],
    "materials":{"wall":{"albedo_texture":"wall.png","texture_wrap":"WRAP"}}})";
  const auto withWrap = [&](const std::string& wrap) {
    std::string text = scene;
    text.replace(text.find("WRAP"), 4, wrap);
    std::ofstream(dir + "/wall.json") << text;
    return dir + "/wall.json";
  };
  const Scene mirrored = loadScene(withWrap("mirror"));
  EXPECT_EQ(mirrored.textures.textures.at(0).wrapS, kWrapMirror);
  EXPECT_EQ(mirrored.textures.textures.at(0).wrapT, kWrapMirror);
  try {
    loadScene(withWrap("border"));
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("materials.wall.texture_wrap"), std::string::npos)
        << e.what();
  }
}

// The glTF version of the textured box (scripts/textured_cornell_box) is the OBJ one: under the
// same grid and its own camera (the scene file's, written as a glTF node), every pixel's albedo
// and position agree. The glTF's float positions are the OBJ's decimals rounded once, so a hit
// moves by ULPs: texture values agree within 10^-4 except at the few pixels where the two pick
// different sides of a tile or brick edge.
TEST(TextureScene, TheGltfBoxIsTheObjBox) {
  const std::string dir = std::string(VOXGI_SOURCE_DIR) + "/scenes/";
  const Scene obj = loadScene(dir + "cornell_box_textured.json");
  Scene gltf = loadScene(dir + "cornell_box_textured.gltf");
  EXPECT_EQ(gltf.textures.textures.size(), 3u);
  const auto emission = [](const Scene& scene) {  // the light's: 17 (1, 12/17, 4/17) is (17, 12, 4)
    for (const Material& m : scene.materials)
      if (m.name == "light") return m.emission;
    return glm::vec3(-1.0f);
  };
  EXPECT_EQ(emission(gltf), glm::vec3(17.0f, 12.0f, 4.0f));
  EXPECT_EQ(emission(obj), emission(gltf));
  gltf.grid = obj.grid;
  const auto gbuffer = [](Scene scene) {
    scene.camera.width = scene.camera.height = 64;
    return runCpuUntil(scene, Settings{}, "gbuffer");
  };
  const BufferSet a = gbuffer(obj), b = gbuffer(gltf);
  const Buffer &albedoA = a.at(BufferId::common_gbuffer_pixel_albedo),
               &albedoB = b.at(BufferId::common_gbuffer_pixel_albedo);
  const Buffer &positionA = a.at(BufferId::common_gbuffer_pixel_position),
               &positionB = b.at(BufferId::common_gbuffer_pixel_position);
  size_t apart = 0;
  for (size_t e = 0; e < 64 * 64; ++e)
    for (int c = 0; c < 3; ++c) {
      ASSERT_NEAR(positionA.get<float>(e, c), positionB.get<float>(e, c), 1e-3) << e;
      apart += std::abs(albedoA.get<float>(e, c) - albedoB.get<float>(e, c)) > 1e-4f;
    }
  EXPECT_LE(apart, 8u);
}

}  // namespace
}  // namespace voxgi::test
