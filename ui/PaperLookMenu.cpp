#include "PaperLookMenu.h"

#include "ActionTexts.h"

#include <QAction>
#include <QActionGroup>
#include <QFileInfo>
#include <QMenu>
#include <QSettings>
#include <QWidget>

namespace pf {

namespace {

QColor toQColor(const std::array<float, 3>& c) {
    return QColor::fromRgbF(c[0], c[1], c[2]);
}

// A small swatch of the paper's colour for the menu entry.
QIcon swatch(const std::array<float, 3>& c) {
    QPixmap p(16, 16);
    p.fill(toQColor(c));
    return QIcon(p);
}

} // namespace

PaperLookMenu::PaperLookMenu(QWidget* window) : QObject(window) {
    auto make = [window](const char* name) {
        auto* a = new QAction(window);
        a->setObjectName(QLatin1String(name));
        return a;
    };
    color_ = make("look.color");
    plain_ = make("look.plain");
    grain_ = make("look.grain");
    image_ = make("look.image");
    textures_ = new QActionGroup(this);
    for (QAction* a : {plain_, grain_, image_}) {
        a->setCheckable(true);
        textures_->addAction(a);
    }
    menu_ = new QMenu(window);
    menu_->addAction(color_);
    menu_->addSeparator();
    menu_->addActions(textures_->actions());

    connect(color_, &QAction::triggered, this, [this] {
        const QColor c = chooseColor ? chooseColor(toQColor(look_.color)) : QColor();
        if (!c.isValid()) return;
        PaperLook next = look_;
        next.color = {static_cast<float>(c.redF()), static_cast<float>(c.greenF()),
                      static_cast<float>(c.blueF())};
        setLook(next);
    });
    connect(plain_, &QAction::triggered, this, [this] {
        PaperLook next = look_;
        next.texture = PaperTexture::Plain;
        setLook(next);
    });
    connect(grain_, &QAction::triggered, this, [this] {
        PaperLook next = look_;
        next.texture = PaperTexture::Grain;
        setLook(next);
    });
    connect(image_, &QAction::triggered, this, [this] {
        const QString path = chooseImage ? chooseImage() : QString();
        PaperLook next = look_;
        QString error;
        if (path.isEmpty() || !setPaperTextureFromText(path, &next, &error)) {
            if (!path.isEmpty() && showError)
                showError(tr("Could not use the picture as paper: %1").arg(error));
            checkCurrentTexture(); // cancelled or refused: the look stays
            return;
        }
        setLook(next);
    });
    restore();
}

void PaperLookMenu::restore() {
    QSettings settings;
    PaperLook look;
    if (const auto c =
            paperColorFromText(settings.value(QLatin1String(kColorSetting)).toString(), nullptr))
        look.color = *c;
    // A picture gone since the last session leaves the paper plain, quietly: the
    // session starts without a dialog about a view setting.
    setPaperTextureFromText(settings.value(QLatin1String(kTextureSetting)).toString(), &look,
                            nullptr);
    look_ = look;
    color_->setIcon(swatch(look_.color));
    checkCurrentTexture();
}

void PaperLookMenu::setLook(const PaperLook& look) {
    look_ = look;
    QSettings settings;
    settings.setValue(QLatin1String(kColorSetting), paperColorText(look.color));
    settings.setValue(QLatin1String(kTextureSetting), paperTextureText(look));
    color_->setIcon(swatch(look_.color));
    checkCurrentTexture();
    retranslate(); // the picture's name is in its entry
    emit lookChanged(look_);
}

void PaperLookMenu::checkCurrentTexture() {
    switch (look_.texture) {
    case PaperTexture::Plain:
        plain_->setChecked(true);
        break;
    case PaperTexture::Grain:
        grain_->setChecked(true);
        break;
    case PaperTexture::Image:
        image_->setChecked(true);
        break;
    }
}

void PaperLookMenu::retranslate() {
    menu_->setTitle(tr("&Paper"));
    color_->setText(tr("Paper &Colour…"));
    plain_->setText(tr("&Plain"));
    grain_->setText(tr("Paper &Grain"));
    image_->setText(
        look_.texture == PaperTexture::Image
            ? tr("P&icture: %1…").arg(ActionTexts::literal(QFileInfo(look_.imagePath).fileName()))
            : tr("P&icture…"));
    image_->setToolTip(tr("Print a picture over the whole sheet"));
}

} // namespace pf
