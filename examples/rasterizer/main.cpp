// kutlog-rasterizer: renders a triangle mesh with a z-buffer, perspective-correct normals and
// coef * F_kutlog shading per 16x16 tile through kutlog's stream API (kutlog::shade, coverage
// as the lane mask), on every core, and times that shading against pow-based Blinn-Phong
// (kutlog::blinn_phong_xsimd, xsimd::pow) from the same cosines.
//   kutlog-rasterizer [WIDTH HEIGHT [FRAMES [OUTPUT.png]]]
#include <OpenImageIO/imagebuf.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <kutlog/lobe.hpp>
#include <kutlog/shade.hpp>
#include <thread>
#include <vector>

namespace {

struct Vec3 {
  float x, y, z;
};
Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec3 operator*(float s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
float dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
Vec3 normalize(Vec3 a) { return (1 / std::sqrt(dot(a, a))) * a; }

struct Mesh {
  std::vector<Vec3> position, normal;
  std::vector<std::array<int, 3>> triangles;
};

// A torus (radii 1 and 0.4), tessellated into quads of two triangles, with exact normals.
Mesh torus(int around, int across) {
  Mesh mesh;
  const float pi = 3.14159265f;
  for (int i = 0; i < around; ++i)
    for (int j = 0; j < across; ++j) {
      const float u = 2 * pi * i / around, v = 2 * pi * j / across;
      const Vec3 center{std::cos(u), 0, std::sin(u)};
      const Vec3 n{std::cos(v) * std::cos(u), std::sin(v), std::cos(v) * std::sin(u)};
      mesh.position.push_back(center + 0.4f * n);
      mesh.normal.push_back(n);
    }
  for (int i = 0; i < around; ++i)
    for (int j = 0; j < across; ++j) {
      const int a = i * across + j, b = ((i + 1) % around) * across + j;
      const int c = ((i + 1) % around) * across + (j + 1) % across, d = i * across + (j + 1) % across;
      mesh.triangles.push_back({a, b, c});
      mesh.triangles.push_back({a, c, d});
    }
  return mesh;
}

struct Camera {
  Vec3 eye{0, 1.6f, 3.0f}, forward, right, up;
  float focal;
  Camera(int width, int height) {
    forward = normalize(Vec3{0, 0, 0} - eye);
    right = normalize(cross(forward, {0, 1, 0}));
    up = cross(right, forward);
    focal = 0.5f * float(height) / std::tan(0.35f);  // vertical field of view 40 degrees
  }
};

// Per pixel after the visibility pass: the nearest triangle and its perspective-correct
// barycentric coordinates.
struct Frame {
  int width, height;
  std::vector<float> depth, b1, b2;
  std::vector<int> triangle;
};

constexpr int kTile = 16;

// Rasterizes every triangle overlapping the rows [row_begin, row_end) of the frame.
void rasterize(const Mesh& mesh, const std::vector<Vec3>& screen, Frame& frame, int row_begin,
               int row_end) {
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto [i0, i1, i2] = mesh.triangles[t];
    const Vec3 a = screen[i0], b = screen[i1], c = screen[i2];  // x, y in pixels, z = 1/w
    if (a.z <= 0 || b.z <= 0 || c.z <= 0) continue;  // behind the camera
    const float area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    if (area <= 0) continue;  // back face: front faces wind clockwise once y points down
    const int x0 = std::max(0, int(std::floor(std::min({a.x, b.x, c.x}))));
    const int x1 = std::min(frame.width - 1, int(std::ceil(std::max({a.x, b.x, c.x}))));
    const int y0 = std::max(row_begin, int(std::floor(std::min({a.y, b.y, c.y}))));
    const int y1 = std::min(row_end - 1, int(std::ceil(std::max({a.y, b.y, c.y}))));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const float px = x + 0.5f, py = y + 0.5f;
        const float w0 = ((b.x - px) * (c.y - py) - (b.y - py) * (c.x - px)) / area;
        const float w1 = ((c.x - px) * (a.y - py) - (c.y - py) * (a.x - px)) / area;
        const float w2 = 1 - w0 - w1;
        if (w0 < 0 || w1 < 0 || w2 < 0) continue;
        const float inverse_w = w0 * a.z + w1 * b.z + w2 * c.z;  // linear in screen space
        const std::size_t p = std::size_t(y) * frame.width + x;
        if (inverse_w <= frame.depth[p]) continue;  // nearer has larger 1/w
        frame.depth[p] = inverse_w;
        frame.triangle[p] = int(t);
        frame.b1[p] = w1 * b.z / inverse_w;  // perspective-correct
        frame.b2[p] = w2 * c.z / inverse_w;
      }
  }
}

struct TileInputs {
  std::array<float, kTile * kTile> t, n_dot_l;
  std::array<std::uint8_t, kTile * kTile> covered;
};

// The cosines N.H and N.L of a tile's pixels, from interpolated unit normals and view
// directions; covered[lane] says whether the pixel shows the mesh.
void gather_tile(const Mesh& mesh, const Frame& frame, const Camera& camera, Vec3 to_light, int tx,
                 int ty, TileInputs& in) {
  for (int j = 0; j < kTile; ++j)
    for (int i = 0; i < kTile; ++i) {
      const int x = tx * kTile + i, y = ty * kTile + j, lane = j * kTile + i;
      const bool inside = x < frame.width && y < frame.height;
      const std::size_t p = inside ? std::size_t(y) * frame.width + x : 0;
      in.covered[lane] = inside && frame.triangle[p] >= 0;
      Vec3 n{0, 0, 1}, v{0, 0, 1};
      if (in.covered[lane]) {
        const auto [i0, i1, i2] = mesh.triangles[frame.triangle[p]];
        const float b1 = frame.b1[p], b2 = frame.b2[p], b0 = 1 - b1 - b2;
        n = normalize(b0 * mesh.normal[i0] + b1 * mesh.normal[i1] + b2 * mesh.normal[i2]);
        const Vec3 world = b0 * mesh.position[i0] + b1 * mesh.position[i1] + b2 * mesh.position[i2];
        v = normalize(camera.eye - world);
      }
      const Vec3 h = normalize(to_light + v);
      in.t[lane] = dot(n, h);
      in.n_dot_l[lane] = dot(n, to_light);
    }
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  const int width = argc > 1 ? std::atoi(argv[1]) : 1920, height = argc > 2 ? std::atoi(argv[2]) : 1080;
  const int frames = argc > 3 ? std::atoi(argv[3]) : 5;
  const char* output = argc > 4 ? argv[4] : "rasterizer.png";
  if (width < kTile || height < kTile || frames < 1) {
    std::fprintf(stderr, "kutlog-rasterizer: error: usage: kutlog-rasterizer [WIDTH>=16 HEIGHT>=16 [FRAMES>=1 [OUTPUT.png]]]\n");
    return 2;
  }
  const float n = 1000;
  const kutlog::Lobe lobe(n, 3, 0.5);
  const Mesh mesh = torus(512, 256);
  const Camera camera(width, height);
  const Vec3 to_light = normalize({-0.4f, 1.0f, 0.6f});
  const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  const int tiles_x = (width + kTile - 1) / kTile, tiles_y = (height + kTile - 1) / kTile;

  // Project once: screen x, y and 1/w.
  std::vector<Vec3> screen;
  for (const Vec3& p : mesh.position) {
    const Vec3 d = p - camera.eye;
    const float z = dot(d, camera.forward);
    screen.push_back({0.5f * width + camera.focal * dot(d, camera.right) / z,
                      0.5f * height - camera.focal * dot(d, camera.up) / z, 1 / z});
  }
  Frame frame{width, height, {}, {}, {}, {}};
  std::vector<float> image(std::size_t(width) * height);
  std::vector<double> kutlog_ms, pow_ms;
  for (int f = 0; f < frames; ++f) {
    frame.depth.assign(image.size(), 0), frame.triangle.assign(image.size(), -1);
    frame.b1.assign(image.size(), 0), frame.b2.assign(image.size(), 0);
    std::vector<std::thread> workers;
    for (unsigned w = 0; w < threads; ++w)
      workers.emplace_back([&, w] {
        const int rows = (height + int(threads) - 1) / int(threads);
        rasterize(mesh, screen, frame, int(w) * rows, std::min(height, int(w + 1) * rows));
      });
    for (std::thread& worker : workers) worker.join();
    workers.clear();
    // Shading, tiles spread over the threads; each thread times its kernel calls only.
    std::vector<double> kutlog_seconds(threads), pow_seconds(threads);
    for (unsigned w = 0; w < threads; ++w)
      workers.emplace_back([&, w] {
        TileInputs in;
        std::array<float, kTile * kTile> specular, baseline;
        for (int tile = int(w); tile < tiles_x * tiles_y; tile += int(threads)) {
          const int tx = tile % tiles_x, ty = tile / tiles_x;
          gather_tile(mesh, frame, camera, to_light, tx, ty, in);
          auto start = std::chrono::steady_clock::now();
          // Both from the same cosines: coef F(N.H) max(N.L, 0) against (N.H)^n max(N.L, 0).
          kutlog::shade(lobe, in.t.data(), in.n_dot_l.data(), specular.data(), specular.size(),
                        in.covered.data());
          auto middle = std::chrono::steady_clock::now();
          kutlog::blinn_phong_xsimd(in.t.data(), baseline.data(), baseline.size(), n);
          for (int lane = 0; lane < kTile * kTile; ++lane) baseline[lane] *= std::max(in.n_dot_l[lane], 0.0f);
          auto end = std::chrono::steady_clock::now();
          kutlog_seconds[w] += std::chrono::duration<double>(middle - start).count();
          pow_seconds[w] += std::chrono::duration<double>(end - middle).count();
          for (int j = 0; j < kTile; ++j)
            for (int i = 0; i < kTile; ++i) {
              const int x = tx * kTile + i, y = ty * kTile + j, lane = j * kTile + i;
              if (x >= width || y >= height) continue;
              image[std::size_t(y) * width + x] =
                  in.covered[lane] ? 0.15f * std::max(in.n_dot_l[lane], 0.0f) + 0.04f * specular[lane] : 1.0f;
            }
        }
      });
    for (std::thread& worker : workers) worker.join();
    // Wall time of the shading kernels: the threads run them in parallel.
    kutlog_ms.push_back(1e3 * *std::max_element(kutlog_seconds.begin(), kutlog_seconds.end()));
    pow_ms.push_back(1e3 * *std::max_element(pow_seconds.begin(), pow_seconds.end()));
  }
  OIIO::ImageBuf out(OIIO::ImageSpec(width, height, 1, OIIO::TypeDesc::FLOAT), image.data());
  for (OIIO::ImageBuf::Iterator<float> it(out); !it.done(); ++it) it[0] = std::min(1.0f, 2 * it[0] / (1 + it[0]));
  if (!out.write(output, OIIO::TypeDesc::UINT8)) {
    std::fprintf(stderr, "kutlog-rasterizer: error: %s\n", out.geterror().c_str());
    return 1;
  }
  const double k_ms = median(kutlog_ms), p_ms = median(pow_ms);
  std::printf("frame %dx%d, %zu triangles, %u threads, median of %d frames, wrote %s\n", width,
              height, mesh.triangles.size(), threads, frames, output);
  std::printf("shading ms/frame: kutlog=%.3f pow_xsimd=%.3f ratio=%.2f\n", k_ms, p_ms, p_ms / k_ms);
  return 0;
}
