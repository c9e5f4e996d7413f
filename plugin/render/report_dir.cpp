// The report directory and the files written into it.
#include "report_dir.h"

#include "capi_util.h"

#include <cctype>
#include <filesystem>
#include <iostream>
#include <system_error>

namespace render {

int make_report_dir(const std::string& dir, bool images) {
    std::error_code ec;
    const std::filesystem::path d(dir);
    std::filesystem::create_directories(images ? d / "images" : d, ec);
    if (ec)
        return error(kRender, "--report " + dir + ": cannot create the directory: " + ec.message());
    return kOk;
}

std::string file_stem(size_t index, const std::string& name) {
    std::string base = name;
    if (base.find('/') != std::string::npos) base = std::filesystem::path(base).filename().string();
    if (base.size() > 4 && base.compare(base.size() - 4, 4, ".xml") == 0)
        base.resize(base.size() - 4);
    for (char& c : base)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.')
            c = '_';
    return std::to_string(index) + "-" + base;
}

int write_report_image(const std::string& dir, const std::string& relative, int width, int height,
                       int channels, const std::vector<float>& pixels, bool display_referred) {
    const std::string path = (std::filesystem::path(dir) / relative).string();
    if (sheafWriteImage(path.c_str(), width, height, channels, pixels.data(),
                        display_referred ? 1 : 0) != SHEAF_OK)
        return error(kRender, last_error());
    return kOk;
}

int write_report_texts(const std::string& dir, const std::string& html, const ResultsMeta& meta,
                       const std::vector<RunResult>& results, bool quiet) {
    const std::filesystem::path d(dir);
    const std::pair<std::string, std::string> files[] = {
        {"report.html", html},
        {"results.json", results_json(meta, results)},
        {"results.csv", results_csv(results)},
    };
    for (const auto& [name, text] : files)
        if (!write_file((d / name).string(), text))
            return error(kRender, (d / name).string() + ": cannot write the file");
    if (!quiet) std::cout << "wrote " << (d / "report.html").string() << "\n";
    return kOk;
}

} // namespace render
