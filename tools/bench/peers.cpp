/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline-peers — symline and OpenCV's line detectors on the same frames, in
 * one run, one thread, image in memory: the time of the detection call alone,
 * and every detector's segments as symline JSON (docs/format.md) for the same
 * scorer (symline-score). Built only where OpenCV with its contrib module
 * ximgproc is installed (Debian: libopencv-dev libopencv-contrib-dev).
 *
 *   symline-peers [--repeat N] OUTDIR FRAME...
 *
 * Writes OUTDIR/DETECTOR/NAME.json (NAME: the frame's file name without its
 * extension) and prints one line per frame and detector on stdout:
 *   DETECTOR WIDTHxHEIGHT NAME FASTEST_MS MEDIAN_MS
 * over N timed calls (default 10) after one untimed call whose output is
 * written. Time is the thread's CPU time (CLOCK_THREAD_CPUTIME_ID): on a shared
 * machine the other processes' turns do not count. The calls are interleaved
 * (round r calls every detector once), so that what they still disturb (caches,
 * clock speed) falls on all detectors alike.
 *
 * The detectors, with their library defaults unless said here:
 *   symline        symline_detect(), symline_config_default()
 *   symline-h1     the horizontal axis at one scale (levels 1)
 *   edlines        cv::ximgproc::EdgeDrawing: detectEdges() + detectLines()
 *   fld            cv::ximgproc::FastLineDetector
 *   lsd            cv::createLineSegmentDetector(LSD_REFINE_STD)
 *   hough          cv::Canny(50, 150) + cv::HoughLinesP(1 px, 1 degree,
 *                  threshold 40, min length 12 px (symline's min_length), gap 3 px)
 * The OpenCV detectors find edges (a painted line's two borders), not centre
 * lines; the scorer measures against centre lines, with its tolerance.
 */
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <sys/stat.h>
#include <time.h>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/ximgproc.hpp>

extern "C" {
#include "hostopts.h"
#include "segjson.h"
#include "symline/detect.h"
}

namespace {

typedef std::vector<cv::Vec4f> Segs;

// Writes OpenCV segments as symline JSON: straight lines, axis by direction.
bool write_segs(const std::string &path, int w, int h, const Segs &s)
{
    FILE *f = std::fopen(path.c_str(), "w");
    if (f == nullptr) {
        return false;
    }
    std::fprintf(f, "{\"width\": %d, \"height\": %d, \"truncated\": false,\n \"segments\": [", w,
                 h);
    for (size_t i = 0; i < s.size(); i++) {
        const float dx = s[i][2] - s[i][0], dy = s[i][3] - s[i][1];
        const long pts = std::lround(std::sqrt((double)dx * dx + (double)dy * dy)) + 1;
        std::fprintf(
            f,
            "%s\n  {\"x0\": %.2f, \"y0\": %.2f, \"x1\": %.2f, \"y1\": %.2f, \"points\": %ld, "
            "\"max_dev\": 0.00, \"kind\": \"line\", \"axis\": \"%s\"}",
            i ? "," : "", s[i][0], s[i][1], s[i][2], s[i][3], pts < 2 ? 2L : pts,
            std::fabs(dy) <= std::fabs(dx) ? "horizontal" : "vertical");
    }
    std::fprintf(f, "\n]}\n");
    return std::fclose(f) == 0;
}

// symline on one frame, its storage allocated once.
struct Symline {
    symline_config cfg;
    std::vector<unsigned char> ws;
    std::vector<symline_segment> segs;
    std::vector<symline_point> pts;
    symline_result res;
    symline_image img;

    Symline(const cv::Mat &m, const symline_config &c) : cfg(c)
    {
        img.width = (uint32_t)m.cols;
        img.height = (uint32_t)m.rows;
        img.stride = (uint32_t)m.step;
        img.data = m.data;
        ws.resize(std::max<size_t>(1, symline_detect_workspace_size(img.width, img.height, &cfg)));
        segs.resize(8192);
        pts.resize(2u * img.width * img.height + 1024u);
        std::memset(&res, 0, sizeof res);
        res.segments = segs.data();
        res.segment_cap = (uint32_t)segs.size();
        res.points = pts.data();
        res.point_cap = (uint32_t)pts.size();
    }
    bool run()
    {
        return symline_detect(&img, &cfg, ws.data(), ws.size(), &res) == SYMLINE_OK;
    }
    bool write(const std::string &path) const
    {
        FILE *f = std::fopen(path.c_str(), "w");
        if (f == nullptr) {
            return false;
        }
        const int bad = segjson_write(f, img.width, img.height, &res);
        return std::fclose(f) == 0 && bad == 0;
    }
};

// A detector on one frame: first() makes its output (written to a file),
// again() repeats the detection; false on failure.
struct Detector {
    std::string name;
    std::function<bool(const cv::Mat &, const std::string &)> first;
    std::function<bool()> again;
};

// CPU time of this thread, ms: what the detection itself took, not the time
// other processes of a shared machine ran in between (they still share caches).
double cpu_ms()
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec / 1e6;
}

// An OpenCV detector given as "detect(image, segments)".
Detector opencv_detector(const std::string &name,
                         std::function<void(const cv::Mat &, Segs &)> detect)
{
    Detector d;
    std::shared_ptr<cv::Mat> frame = std::make_shared<cv::Mat>();
    d.name = name;
    d.first = [detect, frame](const cv::Mat &m, const std::string &out) {
        Segs s;
        *frame = m;
        detect(m, s);
        return write_segs(out, m.cols, m.rows, s);
    };
    d.again = [detect, frame]() {
        Segs s;
        detect(*frame, s);
        return true;
    };
    return d;
}

Detector symline_detector(const std::string &name, const symline_config &cfg)
{
    Detector d;
    std::shared_ptr<std::unique_ptr<Symline>> state = std::make_shared<std::unique_ptr<Symline>>();
    d.name = name;
    d.first = [cfg, state](const cv::Mat &m, const std::string &out) {
        state->reset(new Symline(m, cfg));
        return (*state)->run() && (*state)->write(out);
    };
    d.again = [state]() { return (*state)->run(); };
    return d;
}

std::vector<Detector> detectors()
{
    std::vector<Detector> v;
    symline_config def, h1;
    symline_config_default(&def);
    h1 = def;
    h1.axes = SYMLINE_AXES_HORIZONTAL;
    h1.levels = 1u;
    v.push_back(symline_detector("symline", def));
    v.push_back(symline_detector("symline-h1", h1));

    cv::Ptr<cv::ximgproc::EdgeDrawing> ed = cv::ximgproc::createEdgeDrawing();
    v.push_back(opencv_detector("edlines", [ed](const cv::Mat &m, Segs &s) {
        ed->detectEdges(m);
        ed->detectLines(s);
    }));
    cv::Ptr<cv::ximgproc::FastLineDetector> fld = cv::ximgproc::createFastLineDetector();
    v.push_back(opencv_detector("fld", [fld](const cv::Mat &m, Segs &s) { fld->detect(m, s); }));
    cv::Ptr<cv::LineSegmentDetector> lsd = cv::createLineSegmentDetector(cv::LSD_REFINE_STD);
    v.push_back(opencv_detector("lsd", [lsd](const cv::Mat &m, Segs &s) { lsd->detect(m, s); }));
    v.push_back(opencv_detector("hough", [](const cv::Mat &m, Segs &s) {
        cv::Mat edges;
        std::vector<cv::Vec4i> l;
        cv::Canny(m, edges, 50, 150, 3);
        cv::HoughLinesP(edges, l, 1, CV_PI / 180, 40, 12, 3);
        s.resize(l.size());
        for (size_t i = 0; i < l.size(); i++) {
            s[i] = cv::Vec4f((float)l[i][0], (float)l[i][1], (float)l[i][2], (float)l[i][3]);
        }
    }));
    return v;
}

std::string stem(const std::string &path)
{
    const size_t slash = path.find_last_of('/');
    std::string b = slash == std::string::npos ? path : path.substr(slash + 1);
    const size_t dot = b.find_last_of('.');
    return dot == std::string::npos ? b : b.substr(0, dot);
}

int usage(FILE *f)
{
    std::fprintf(
        f, "usage: symline-peers [--repeat N] OUTDIR FRAME...\n"
           "Times symline and OpenCV's line detectors (one thread, the detection call\n"
           "only; N calls each, default 10, interleaved) and writes\n"
           "OUTDIR/DETECTOR/NAME.json. Prints: DETECTOR WIDTHxHEIGHT NAME FASTEST_MS MEDIAN_MS\n"
           "Options take --opt VALUE or --opt=VALUE; --version prints the version.\n");
    return f == stdout ? 0 : 2;
}

} // namespace

int main(int argc, char **argv)
{
    static const struct option longopts[] = {{"help", no_argument, nullptr, HOSTOPTS_HELP},
                                             {"version", no_argument, nullptr, HOSTOPTS_VERSION},
                                             {"repeat", required_argument, nullptr, 'r'},
                                             {nullptr, 0, nullptr, 0}};
    const char *const prog = "symline-peers";
    int repeat = 10, c;
    long v;
    while ((c = hostopts_next(argc, argv, ":h", longopts, prog, prog)) != -1) {
        switch (c) {
        case HOSTOPTS_HELP: return usage(stdout);
        case HOSTOPTS_VERSION: hostopts_version(prog); return 0;
        case 'r':
            if (hostopts_long(optarg, 1, 100000, &v) != 0) {
                return hostopts_usage_error(prog, prog, "--repeat needs a number 1..100000");
            }
            repeat = static_cast<int>(v);
            break;
        default: return HOSTOPTS_USAGE;
        }
    }
    int i = optind;
    if (argc - i < 2) {
        return hostopts_usage_error(prog, prog, "needs OUTDIR and at least one FRAME");
    }
    cv::setNumThreads(1);
    const std::string outdir = argv[i++];
    std::vector<Detector> dets = detectors();
    mkdir(outdir.c_str(), 0777);
    for (const Detector &d : dets) {
        const std::string dir = outdir + "/" + d.name;
        struct stat st;
        mkdir(dir.c_str(), 0777);
        if (stat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode)) {
            std::fprintf(stderr, "symline-peers: cannot make the folder '%s'\n", dir.c_str());
            return 2;
        }
    }
    for (; i < argc; i++) {
        const cv::Mat m = cv::imread(argv[i], cv::IMREAD_GRAYSCALE);
        if (m.empty() || !m.isContinuous()) {
            std::fprintf(stderr, "symline-peers: cannot read '%s'\n", argv[i]);
            return 2;
        }
        std::vector<std::vector<double>> ms(dets.size());
        for (size_t k = 0; k < dets.size(); k++) {
            const std::string out = outdir + "/" + dets[k].name + "/" + stem(argv[i]) + ".json";
            if (!dets[k].first(m, out)) {
                std::fprintf(stderr, "symline-peers: %s failed on '%s'\n", dets[k].name.c_str(),
                             argv[i]);
                return 1;
            }
        }
        for (int r = 0; r < repeat; r++) {
            for (size_t k = 0; k < dets.size(); k++) {
                const double t0 = cpu_ms();
                if (!dets[k].again()) {
                    std::fprintf(stderr, "symline-peers: %s failed on '%s'\n", dets[k].name.c_str(),
                                 argv[i]);
                    return 1;
                }
                ms[k].push_back(cpu_ms() - t0);
            }
        }
        for (size_t k = 0; k < dets.size(); k++) {
            std::vector<double> &v = ms[k];
            std::sort(v.begin(), v.end());
            std::printf("%s %dx%d %s %.4f %.4f\n", dets[k].name.c_str(), m.cols, m.rows,
                        stem(argv[i]).c_str(), v[0], v[v.size() / 2]);
        }
        std::fflush(stdout);
    }
    return 0;
}
