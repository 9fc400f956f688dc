; Two cubes into a tray on a raised platform; a can stands in the middle of
; the tray and leaves room for neither. The goal says nothing about the can.
(define (problem blind2-p02)
  (:domain blind2-on)
  (:objects a b c - obj
            start tray side - region)
  (:init (on a start) (on b start) (on c tray) (handempty))
  (:goal (and (on a tray) (on b tray))))
