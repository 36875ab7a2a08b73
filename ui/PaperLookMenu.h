#pragma once

#include "PaperLook.h"

#include <QColor>
#include <QObject>
#include <functional>

class QAction;
class QActionGroup;
class QMenu;
class QWidget;

namespace pf {

// View ▸ Paper: the paper's colour and texture (plain, the built-in grain, or a picture
// the user picks). A look, not physics, so it is no undo step and not in the sheet
// file; QSettings keeps it for the next session, like the other view settings.
class PaperLookMenu : public QObject {
    Q_OBJECT

  public:
    static constexpr const char* kColorSetting = "look/color";
    // plain, grain or the picture's path (setPaperTextureFromText)
    static constexpr const char* kTextureSetting = "look/texture";

    // The actions are children of `window`, named look.color, look.plain, look.grain and
    // look.image, so that the window's action texts and tests find them.
    explicit PaperLookMenu(QWidget* window);

    QMenu* menu() const { return menu_; }
    const PaperLook& look() const { return look_; }
    void retranslate();

    // The questions asked, replaceable by tests: an invalid colour or an empty path
    // means cancelled.
    std::function<QColor(const QColor& current)> chooseColor;
    std::function<QString()> chooseImage;
    std::function<void(const QString&)> showError;

  signals:
    void lookChanged(const PaperLook& look);

  private:
    void restore();
    void setLook(const PaperLook& look);
    void checkCurrentTexture();

    QMenu* menu_ = nullptr;
    QActionGroup* textures_ = nullptr;
    QAction *color_ = nullptr, *plain_ = nullptr, *grain_ = nullptr, *image_ = nullptr;
    PaperLook look_;
};

} // namespace pf
