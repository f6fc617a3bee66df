// render_bench: end-to-end cost of recording a game's frames. Renders 1280x720 frames of ~50
// moving circles offscreen, reads each back and hands it to the asynchronous PNG writer, then
// prints frames per second and bytes per frame. Not a test: the figures depend on the machine.
// Each offscreen back end built (EGL, OSMesa) is measured in turn in the same run, on the same
// frames, so their figures compare (issue 25); --gl egl or --gl osmesa measures one.
//
// Usage: render_bench [--frames N] [--circles N] [--size WxH] [--gl all|egl|osmesa] [--out DIR] [--keep]
#include "rube/render/draw_list.hpp"
#include "rube/render/frame_writer.hpp"
#include "rube/render/palette.hpp"
#include "rube/render/render_context.hpp"
#include "rube/render/renderer.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include <sys/resource.h>
#include <unistd.h>

using namespace rube::render;

namespace {

struct Options {
    int frames = 600;
    int circles = 50;
    FrameSize size{1280, 720};
    std::filesystem::path out;
    bool keep = false;
    std::vector<GlBackend> backends; // empty: every back end built
};

Options parse(int argc, char** argv) {
    Options options;
    for (int i = 1; i < argc; ++i) {
        std::string arg = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) throw std::runtime_error(arg + " needs a value");
            return argv[++i];
        };
        if (arg == "--frames") options.frames = std::stoi(value());
        else if (arg == "--circles") options.circles = std::stoi(value());
        else if (arg == "--size") {
            std::string v = value();
            if (std::sscanf(v.c_str(), "%dx%d", &options.size.width, &options.size.height) != 2)
                throw std::runtime_error("--size wants WxH");
        } else if (arg == "--gl") {
            const std::string name = value();
            if (name == "all") options.backends.clear();
            else if (const auto backend = glBackendFromName(name); backend && *backend != GlBackend::automatic)
                options.backends = {*backend};
            else throw std::runtime_error("--gl wants all, egl or osmesa");
        } else if (arg == "--out") options.out = value();
        else if (arg == "--keep") options.keep = true;
        else throw std::runtime_error("unknown argument " + arg + " (see the comment at the top of render_bench.cpp)");
    }
    return options;
}

// A ball moving on a closed-form path (no physics here): bouncing between the walls.
struct Ball {
    Point start;
    Point velocity;
    float radius;
};

float bounce(float start, float speed, float t, float lo, float hi) {
    // Reflecting motion on [lo, hi] is a triangle wave of period 2 (hi - lo).
    float span = hi - lo;
    float s = std::fmod(start - lo + speed * t, 2.0f * span);
    if (s < 0) s += 2.0f * span;
    return lo + (s <= span ? s : 2.0f * span - s);
}

void buildFrame(DrawList& list, const std::vector<Ball>& balls, float t, int frame, double fps) {
    const Palette& palette = Palette::greybox();
    const Style ground{palette["ground"], palette["ground_outline"], 1.5f};
    const Style ball{palette["ball"], palette["ball_outline"], 1.5f};
    list.clear();
    list.background = palette["background"];
    list.capsule({-15.5f, -8.5f}, {15.5f, -8.5f}, 0.25f, ground);
    list.capsule({-15.5f, -8.5f}, {-15.5f, 8.5f}, 0.25f, ground);
    list.capsule({15.5f, -8.5f}, {15.5f, 8.5f}, 0.25f, ground);
    list.box({0.0f, -4.0f}, {3.0f, 0.3f}, 0.2f * std::sin(t), {palette["box"], palette["box_outline"], 1.5f});
    for (std::size_t i = 0; i < balls.size(); ++i) {
        const Ball& b = balls[i];
        Point p{bounce(b.start.x, b.velocity.x, t, -15.25f + b.radius, 15.25f - b.radius),
                bounce(b.start.y, b.velocity.y, t, -8.25f + b.radius, 8.5f - b.radius)};
        if (i % 10 == 0) {
            Point trail[8];
            for (int k = 0; k < 8; ++k) {
                float tk = t - 0.05f * static_cast<float>(7 - k);
                trail[k] = {bounce(b.start.x, b.velocity.x, tk, -15.25f + b.radius, 15.25f - b.radius),
                            bounce(b.start.y, b.velocity.y, tk, -8.25f + b.radius, 8.5f - b.radius)};
            }
            list.polyline(trail, 3.0f, palette["trail"].withAlpha(0), palette["trail"]);
        }
        list.circleWithSpoke(p, b.radius, -b.velocity.x / b.radius * t, ball);
    }
    list.ring({6.0f, 2.0f}, 0.5f + 2.0f * std::fmod(t, 1.0f), 3.0f, palette["explosion"]);
    char hud[128];
    std::snprintf(hud, sizeof hud, "frame %04d   t = %6.2f s   %5.1f fps", frame, static_cast<double>(t), fps);
    list.text(16, 12, hud, palette["hud_text"], 2);
}

// User plus system time of every thread so far: the cost that does not depend on how busy
// the (shared) machine is, unlike frames per second.
double cpuSeconds() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
           static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) / 1e6;
}

// Renders, reads back and writes options.frames frames through `backend` into `folder`, and prints
// the figures under the back end's name.
void bench(const Options& options, GlBackend backend, const std::vector<Ball>& balls,
           const std::filesystem::path& folder) {
    auto context = createOffscreenContext(options.size, backend);
    Renderer renderer(*context);
    const Camera camera = Camera::fitting({{-16.0f, -9.0f}, {16.0f, 9.0f}}, options.size);
    DrawList list;
    FrameWriter writer(folder);

    using Clock = std::chrono::steady_clock;
    double renderSeconds = 0.0;
    double fps = 0.0;
    auto start = Clock::now();
    const double cpuStart = cpuSeconds();
    for (int frame = 0; frame < options.frames; ++frame) {
        auto before = Clock::now();
        buildFrame(list, balls, static_cast<float>(frame) / 60.0f, frame, fps);
        renderer.draw(list, camera);
        Image image = writer.spareImage();
        renderer.readPixels(image);
        renderSeconds += std::chrono::duration<double>(Clock::now() - before).count();
        char name[32];
        std::snprintf(name, sizeof name, "frame_%05d.png", frame);
        writer.write(std::move(image), name);
        fps = (frame + 1) / std::chrono::duration<double>(Clock::now() - start).count();
    }
    writer.finish();
    double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    double cpuPerFrame = (cpuSeconds() - cpuStart) / options.frames;

    std::printf("render_bench [%s]: %d frames %dx%d, %d circles (%zu instances, %d draw call per frame)\n",
                std::string(context->backendName()).c_str(), options.frames, options.size.width, options.size.height,
                options.circles, renderer.lastStats().instances, renderer.lastStats().drawCalls);
    std::printf("  end to end      %.1f fps (%.2f s)\n", options.frames / seconds, seconds);
    std::printf("  render+readback %.2f ms per frame (main thread)\n", 1000.0 * renderSeconds / options.frames);
    std::printf("  cpu             %.2f ms per frame (all threads)\n", 1000.0 * cpuPerFrame);
    std::printf("  PNG             %.0f bytes per frame (%lld frames written)\n",
                static_cast<double>(writer.bytesWritten()) / static_cast<double>(writer.framesWritten()),
                static_cast<long long>(writer.framesWritten()));
}

} // namespace

int main(int argc, char** argv) try {
    Options options = parse(argc, argv);
    std::filesystem::path folder = options.out;
    if (folder.empty()) {
        std::string pattern = (std::filesystem::temp_directory_path() / "rube-render-bench-XXXXXX").string();
        if (::mkdtemp(pattern.data()) == nullptr)
            throw std::runtime_error("cannot make a temporary folder: " + std::string(std::strerror(errno)));
        folder = pattern;
    }

    std::vector<Ball> balls;
    std::srand(1); // the same scene on every run
    for (int i = 0; i < options.circles; ++i) {
        auto uniform = [] { return static_cast<float>(std::rand()) / static_cast<float>(RAND_MAX); };
        balls.push_back({{-14.0f + 28.0f * uniform(), -7.0f + 14.0f * uniform()},
                         {-6.0f + 12.0f * uniform(), -6.0f + 12.0f * uniform()},
                         0.3f + 0.5f * uniform()});
    }

    std::vector<GlBackend> backends = options.backends;
    if (backends.empty()) {
        for (GlBackend backend : {GlBackend::egl, GlBackend::osmesa})
            if (glBackendBuilt(backend)) backends.push_back(backend);
    }
    // One back end at a time: glad's function table is global, and each context loads its own.
    for (GlBackend backend : backends) bench(options, backend, balls, folder / std::string(glBackendName(backend)));
    std::printf("  frames in       %s%s\n", folder.string().c_str(),
                options.keep || !options.out.empty() ? "" : " (removed)");
    if (!options.keep && options.out.empty()) std::filesystem::remove_all(folder);
    return 0;
} catch (const std::exception& e) {
    std::fprintf(stderr, "render_bench: %s\n", e.what());
    return 1;
}
