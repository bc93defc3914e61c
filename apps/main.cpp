// lucent: renders light scattering inside translucent objects (see README.md).
#include <cstdio>
#include <exception>
#include <map>

#include "apps/commands.h"
#include "apps/heap_pages.h"
#include "apps/mpi_ranks.h"
#include "core/error.h"

int main(int argc, char** argv) {
    lucent::serveHeapFromHugePages();
    CLI::App app{"Lucent: single scattering in translucent objects, rendered by an OpenGL raster pipeline"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "lucent 0.1.0");
    std::map<CLI::App*, lucent::Command> commands;
    for (auto add :
         {lucent::addPreprocessCommand, lucent::addRenderCommand, lucent::addViewCommand, lucent::addInfoCommand,
          lucent::addBenchCommand, lucent::addTransportCommand, lucent::addPresetsCommand, lucent::addMethodsCommand}) {
        const size_t before = app.get_subcommands({}).size();
        lucent::Command run = add(app);
        commands[app.get_subcommands({})[before]] = std::move(run);
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::fprintf(stderr, "lucent: error: %s\n", e.what());
        return 2;
    }
    try {
        for (auto& [sub, run] : commands)
            if (sub->parsed()) run();
    } catch (const lucent::Error& e) {
        std::fprintf(stderr, "lucent: error: %s\n", e.what());
        return 1;
    } catch (const lucent::QuietExit& e) {
        return e.code;  // another rank said why
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "lucent: error: out of memory\n");
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "lucent: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
