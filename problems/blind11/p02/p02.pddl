;; A carton goes from the table into the one free place of a packed row
;; on a shelf board: tall books stand on either side of it, 3 cm from the
;; carton's faces each side when it is centred.
(define (problem blind11-p02)
  (:domain blind11-row)
  (:objects carton book-1 book-2 book-3 book-4 - item
            counter row-1 row-2 gap row-3 row-4 - place)
  (:init (stands carton counter) (taken counter)
         (stands book-1 row-1) (taken row-1)
         (stands book-2 row-2) (taken row-2)
         (stands book-3 row-3) (taken row-3)
         (stands book-4 row-4) (taken row-4)
         (free-hand))
  (:goal (and (stands carton gap) (free-hand))))
