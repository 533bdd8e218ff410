// ViewerCommand: what a key, a menu item or a button asks of the viewer (the key bindings: README's key list).
#pragma once

namespace trazo {

enum class ViewerCommand {
    FrameScene, ResetCamera, Screenshot, SaveScene, Quit,
    Undo, Redo,
    FitView, ActualPixels, ZoomIn, ZoomOut,
    Grab,     // G: move the selection with the mouse
    Confirm,  // Enter, or a left click during a move
    Cancel,   // Escape, or a right click during a move: ends the move, else clears the selection
    Delete,
    Duplicate,  // then a move of the copy, as G
    AddSphere,  // at the point the camera looks at
    OpenPrompt, // the Open panel's path field takes the keys
    FocusPick,  // Shift+F: the next click on the image sets the camera's FocalDistance (again: cancels)
};

}  // namespace trazo
