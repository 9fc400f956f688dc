;; A two-level shelf: the carton on the lower step goes up to the small
;; upper board, the jar up there comes down to the lower step. The upper
;; spot holds one of them at a time; nothing symbolic says so.
(define (problem blind10-p07)
  (:domain blind10-shelf)
  (:objects carton jar - thing
            low-a low-b - low
            top-spot - high)
  (:init (stands carton low-a) (stands jar top-spot) (hand-free))
  (:goal (and (stands carton top-spot) (stands jar low-b))))
