#pragma once
/// WindowInput: what a window reports of the keyboard and the mouse, in the renderer's own words
/// so that a listener (the game) needs no GLFW header and a test can call it with made-up events.

namespace rube::render {

/// The keys the game listens to; every other key arrives as `other` and is ignored.
enum class Key {
    space,
    escape,
    enter,
    backspace,
    deleteKey,
    tab,
    left,
    right,
    up,
    down,
    leftBracket,
    rightBracket,
    control, ///< either Control key: the play window's Ctrl+Z and Ctrl+Y
    a,
    b,
    c,
    d,
    e,
    f,
    g,
    h,
    i,
    j,
    k,
    l,
    m,
    n,
    o,
    p,
    q,
    r,
    s,
    t,
    u,
    v,
    w,
    x,
    y,
    z,
    other,
};

/// What a key did: went down, repeats while held (the system's auto-repeat), or went up.
enum class KeyAction { press, repeat, release };

/// The mouse buttons the game listens to.
enum class MouseButton { left, right, middle, other };

/// Receives a window's input. The window calls these from RenderContext::present() (where it
/// polls its events), on the thread that drew the frame. Positions are in framebuffer pixels
/// from the top-left corner, the way primitive::Text is placed, so high-DPI screens need no care
/// from the listener.
class InputListener {
public:
    virtual ~InputListener() = default;
    /// The cursor moved to (x, y).
    virtual void cursorMoved(float x, float y) = 0;
    /// A mouse button went down (pressed) or up, at the last reported cursor position.
    virtual void mouseButton(MouseButton button, bool pressed) = 0;
    /// The wheel turned: positive is away from the user (up), one notch is 1.
    virtual void scrolled(float notches) = 0;
    /// A key went down, repeated while held, or went up.
    virtual void key(Key key, KeyAction action) = 0;
    /// A character was typed (a Unicode code point, after the keyboard layout), after the key()
    /// of the key that typed it. Listeners that take no text ignore it.
    virtual void typed(char32_t codePoint) { (void)codePoint; }
};

} // namespace rube::render
