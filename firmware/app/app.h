/*
 * app.h — the frame loop (app.c): the firmware's edge between the pure pipeline and the platform.
 */
#ifndef APP_H
#define APP_H

/* Boot, then render FW_FRAMES frames of FW_SCENE (or until Q); returns the exit status. */
int app_run(void);

#endif /* APP_H */
