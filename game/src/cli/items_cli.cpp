// `rube items [--sheet DIR]`: the catalogue of part kinds, or their pictures.
#include "command_line.hpp"

#include "items_command.hpp"

#include <iostream>
#include <string>

#include <unistd.h>

namespace rube::game::cli {

namespace {

// `rube items [--sheet DIR]`: the catalogue of part kinds, or their pictures.
class ItemsCommand final : public Subcommand {
public:
    explicit ItemsCommand(CLI::App& app);
    bool chosen() const override { return static_cast<bool>(*command_); }
    ExitCode run() override;

private:
    CLI::App* command_ = nullptr;
    ItemsOptions options_;
    std::string size_ = "320x240";
    CLI::Option* sheetOption_ = nullptr;
    CLI::Option* sizeOption_ = nullptr;
};

ItemsCommand::ItemsCommand(CLI::App& app) {
    command_ = app.add_subcommand("items",
                                  "List every part kind with its keys, defaults, units and meaning; or draw them");
    command_->footer("The same catalogue, with pictures, is game/items.md. Every picture is one kind's default\n"
                     "  item drawn as 'rube run' draws levels, with its name, its inventory icon in the top right\n"
                     "  corner and a 1 m bar (each picture is framed to its part). A progress line is shown only\n"
                     "  when stderr is a terminal. Regenerate the committed pictures with\n"
                     "  rube items --sheet game/items.\n"
                     "Exit status: 0 done, 1 no GL context, 2 bad usage or a folder that cannot be written.");
    sheetOption_ = command_
                       ->add_option("--sheet", options_.sheet,
                                    "Draw one labelled PNG per kind into DIR/<kind>.png (created if missing)")
                       ->type_name("DIR");
    sizeOption_ = command_->add_option("--size", size_, "Each picture's size in pixels (default 320x240)")
                      ->type_name("WxH")
                      ->check(CLI::Validator(frameSizeError, ""));
}

ExitCode ItemsCommand::run() {
    if (*sheetOption_ && options_.sheet.empty())
        return usageError("--sheet: expected a folder, got ''", "rube items --help");
    if (*sizeOption_ && !*sheetOption_) return usageError("--size requires --sheet", "rube items --help");
    options_.size = *parseFrameSize(size_); // the validator has accepted it, or it is the default
    options_.progress = ::isatty(STDERR_FILENO) == 1;
    return listItems(options_, std::cout, std::cerr);
}

} // namespace

std::unique_ptr<Subcommand> addItemsCommand(CLI::App& app) { return std::make_unique<ItemsCommand>(app); }

} // namespace rube::game::cli
