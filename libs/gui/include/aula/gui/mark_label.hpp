#pragma once
// A referee window's mark: "Mark: -" until the window shows one, large and bold, wrapped, from
// the top left. A hot reload starts a new episode whose mark is not the last one's: clearFor
// clears it. The font is set, not a style sheet, so that a window can size the label from it now.
#include <QLabel>

namespace aula::gui {

class MarkLabel : public QLabel {
 public:
  explicit MarkLabel(QWidget* parent = nullptr) : QLabel("Mark: -", parent) {
    QFont font = this->font();
    font.setPixelSize(22);
    font.setBold(true);
    setFont(font);
    setWordWrap(true);
    setAlignment(Qt::AlignLeft | Qt::AlignTop);
  }

  // Clears the mark when `episode` is not the one it last saw; true when it did (the window then
  // says what it shows).
  bool clearFor(int episode) {
    if (episode == episode_) return false;
    episode_ = episode;
    setText("Mark: -");
    return true;
  }

 private:
  int episode_ = 0;
};

}  // namespace aula::gui
