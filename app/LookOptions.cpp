#include "LookOptions.h"

#include "CommandLine.h"

namespace pf::cli {

void addLookOptions(QCommandLineParser& parser) {
    parser.addOptions({
        {QStringLiteral("paper-color"),
         QStringLiteral("Paper colour: #rrggbb or a name such as ivory (default #f2f0e6)."),
         QStringLiteral("colour")},
        {QStringLiteral("texture"),
         QStringLiteral("Paper texture: plain (default), grain (built-in paper grain) or an "
                        "image file, stretched over the sheet."),
         QStringLiteral("plain|grain|file")},
    });
}

PaperLook lookFromOptions(const QCommandLineParser& parser, QStringList* inputs) {
    PaperLook look;
    QString error;
    if (parser.isSet(QStringLiteral("paper-color"))) {
        const auto color = paperColorFromText(parser.value(QStringLiteral("paper-color")), &error);
        if (!color) throw UsageError{QStringLiteral("--paper-color: ") + error};
        look.color = *color;
    }
    if (parser.isSet(QStringLiteral("texture"))) {
        const QString texture = parser.value(QStringLiteral("texture"));
        if (!setPaperTextureFromText(texture, &look, &error))
            throw UsageError{QStringLiteral("--texture: ") + error};
        if (look.texture == PaperTexture::Image && inputs) *inputs << texture;
    }
    return look;
}

} // namespace pf::cli
